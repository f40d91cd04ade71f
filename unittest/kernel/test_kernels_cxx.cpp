/* test_kernels.c compiled as C++: the kernel header must be valid C++ too */
#include "test_kernels.c"
