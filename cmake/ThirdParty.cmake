# Third-party headers come in as system includes (imported targets, and /usr/include itself), so
# their own warnings do not show. GCC's middle-end warnings are the exception: they judge the code
# after inlining and fire inside system headers all the same, on false positives that the code
# including them cannot mend. They are silenced where they arise, and only there.

# Eigen's vectorised loads of small fixed-size matrices through GCC's AVX-512 intrinsics
# (avx512fintrin.h, with -march=native): "array subscript is partly outside array bounds" (GCC bug
# 106247, Eigen issue 2506) and "may be used uninitialized" (GCC bug 105593). aerobreak_eigen is
# Eigen for the fitting, the search and the growth code, and for whatever includes their headers.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
add_library(aerobreak_eigen INTERFACE)
target_link_libraries(aerobreak_eigen INTERFACE Eigen3::Eigen)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(aerobreak_eigen INTERFACE -Wno-array-bounds -Wno-maybe-uninitialized)
endif()

# GCC 12's libstdc++: std::string's insert and replace, inlined, "may overlap" (-Wrestrict, GCC bug
# 105329, fixed in GCC 13).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  add_compile_options(-Wno-restrict)
endif()
