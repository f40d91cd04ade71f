/* test_mixing_terms.c compiled as C++: sph_mixing.h must be valid C++ too */
#include "test_mixing_terms.c"
