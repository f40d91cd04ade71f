/* test_flow_terms.c compiled as C++: the flow and EOS headers must be valid C++ too */
#include "test_flow_terms.c"
