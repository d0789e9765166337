# Flags per compiler: GCC and clang (Apple's included) take one spelling, MSVC another, and a
# flag one of them lacks is left out rather than guessed.
include(CheckCXXCompilerFlag)

if(MSVC)
    set(CMAKE_CXX_FLAGS_RELEASE "/O2 /DNDEBUG")
    add_compile_options(/W4 /permissive- /utf-8 /EHsc)
    # M_PI and friends; no min/max macros from <windows.h>.
    add_compile_definitions(_USE_MATH_DEFINES NOMINMAX)
    set(PATHLAB_WARNINGS_AS_ERRORS_FLAG /WX)
else()
    set(CMAKE_CXX_FLAGS_RELEASE "-O3 -DNDEBUG")
    add_compile_options(-Wall -Wextra)
    set(PATHLAB_WARNINGS_AS_ERRORS_FLAG -Werror)
endif()

if(PATHLAB_NATIVE)
    check_cxx_compiler_flag(-march=native PATHLAB_HAS_MARCH_NATIVE)
    if(PATHLAB_HAS_MARCH_NATIVE)
        add_compile_options(-march=native)
    else()
        message(STATUS "PATHLAB_NATIVE: this compiler takes no -march=native; building without")
    endif()
endif()

# No fused multiply-adds the source did not write: GCC (in C++) and clang fuse a*b+c into one FMA
# wherever the instruction set has one (-march=native on x86-64, every ARM64), which changes the
# last bits of every image. Without, an image is the same bit for bit with PATHLAB_NATIVE on or
# off, and the faster native build still matches the grader's stored references. MSVC does not
# contract unless told to (/fp:contract).
check_cxx_compiler_flag(-ffp-contract=off PATHLAB_HAS_FP_CONTRACT_OFF)
if(PATHLAB_HAS_FP_CONTRACT_OFF)
    set(PATHLAB_NO_FP_CONTRACTION -ffp-contract=off)
else()
    set(PATHLAB_NO_FP_CONTRACTION "")
endif()

# pathlab_strict_warnings(TARGET...): warnings are errors in these targets when
# PATHLAB_WARNINGS_AS_ERRORS is on (the framework, the labs, the viewer; CI's clang build).
function(pathlab_strict_warnings)
    if(PATHLAB_WARNINGS_AS_ERRORS)
        foreach(target IN LISTS ARGN)
            target_compile_options(${target} PRIVATE ${PATHLAB_WARNINGS_AS_ERRORS_FLAG})
        endforeach()
    endif()
endfunction()
