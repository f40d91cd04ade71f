# kernel tests (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)
# the kernels of sph_kernels.h, compiled as C99 and as C++
add_header_test(test_kernels kernel/test_kernels.c C_EXTENSIONS OFF)
add_header_test_cxx(test_kernels_cxx kernel/test_kernels_cxx.cpp)

foreach(dim 1 2 3)
  sphthermal_test(kernel.normalisation.${dim}d LABELS unit COMMAND test_kernels normalisation ${dim})
endforeach()
foreach(check derivative support shape over_q)
  sphthermal_unit_checks(kernel test_kernels ${check})
  sphthermal_unit_checks(kernel.cxx test_kernels_cxx ${check})
endforeach()
sphthermal_test(kernel.cxx.normalisation.3d LABELS unit COMMAND test_kernels_cxx normalisation 3)
