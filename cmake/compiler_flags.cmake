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
    # A test that builds a copy of the kit only to run it, timing nothing, may ask for less
    # (docs.fifth_lab: -O1, a third less compile time); the kit's builds take the default.
    set(PATHLAB_RELEASE_OPTIMIZATION "-O3" CACHE STRING "GCC/clang optimisation of Release builds")
    set(CMAKE_CXX_FLAGS_RELEASE "${PATHLAB_RELEASE_OPTIMIZATION} -DNDEBUG")
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

# Source files named from the kit's folder in the programs (__FILE__ in a failed check's message):
# no host path is compiled into the viewer that the grader copies into a submission's sandbox,
# where a lab could read it. framework/src/support/check.cpp finds the file from where the program runs.
check_cxx_compiler_flag(-ffile-prefix-map=a=b PATHLAB_HAS_FILE_PREFIX_MAP)
if(PATHLAB_HAS_FILE_PREFIX_MAP)
    add_compile_options(-ffile-prefix-map=${PROJECT_SOURCE_DIR}/=)
endif()

# Math functions that never set errno (-fno-math-errno): GCC and clang then inline std::sqrt with
# no branch around it. MSVC's sqrt does not set errno in the first place.
check_cxx_compiler_flag(-fno-math-errno PATHLAB_HAS_NO_MATH_ERRNO)
if(PATHLAB_HAS_NO_MATH_ERRNO)
    set(PATHLAB_NO_MATH_ERRNO -fno-math-errno)
else()
    set(PATHLAB_NO_MATH_ERRNO "")
endif()

# pathlab_strict_warnings(TARGET...): warnings are errors in these targets when
# PATHLAB_WARNINGS_AS_ERRORS is on: every target compiled from PathLab's own code (the
# framework and its image plug-in, the labs, the viewer, the grader, the benchmark, the tests),
# none compiled from a third party's (Dear ImGui). CI's builds turn it on;
# students' builds leave it off, so a newer compiler's new warning never stops them.
function(pathlab_strict_warnings)
    if(PATHLAB_WARNINGS_AS_ERRORS)
        foreach(target IN LISTS ARGN)
            target_compile_options(${target} PRIVATE ${PATHLAB_WARNINGS_AS_ERRORS_FLAG})
        endforeach()
    endif()
endfunction()

# PATHLAB_SANITIZE: the sanitizers every target is compiled and linked with, as -fsanitize takes
# them ("address,undefined", "thread"; empty, the default, for none). Shared libraries included:
# the image plug-in too, whose C interface is the same whichever C++ library it is built against.
# Not the lab library `grader batch` compiles from a submission at run time
# (apps/viewer/CMakeLists.txt): a student's code is graded as students build it.
set(PATHLAB_SANITIZE "" CACHE STRING
    "Sanitizers for every target, as -fsanitize takes them: address,undefined or thread")
if(PATHLAB_SANITIZE)
    if(MSVC)
        message(FATAL_ERROR "PATHLAB_SANITIZE: the kit passes -fsanitize, which MSVC does not take")
    endif()
    # Whole stacks in the reports, even through -O3 code, with file and line (-g1: line tables
    # only, which cost little to compile).
    set(pathlab_sanitize_flags -fsanitize=${PATHLAB_SANITIZE} -fno-omit-frame-pointer -g1)
    string(REPLACE "," ";" pathlab_sanitizers "${PATHLAB_SANITIZE}")
    if("undefined" IN_LIST pathlab_sanitizers)
        # Undefined behaviour stops the program, so a report fails its test instead of scrolling by.
        list(APPEND pathlab_sanitize_flags -fno-sanitize-recover=undefined)
    endif()
    add_compile_options(${pathlab_sanitize_flags})
    add_link_options(${pathlab_sanitize_flags})
    # A sanitized program reserves terabytes of address space for its shadow memory, so the
    # grader's runs get no address-space limit (RLIMIT_AS) there; their other limits stand.
    add_compile_definitions(PATHLAB_SANITIZED)
endif()
