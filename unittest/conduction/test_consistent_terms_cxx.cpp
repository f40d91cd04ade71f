/* test_consistent_terms.c compiled as C++: the consistency header must be valid C++ too */
#include "test_consistent_terms.c"
