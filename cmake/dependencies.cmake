# PathLab's libraries, found the way each platform provides them: CMake config packages first
# (vcpkg, Homebrew, Debian ships most of them too), pkg-config second (Dear ImGui on Debian and
# Ubuntu), a source folder last (Dear ImGui where no package has it).
# Each ends as one target the rest of the build links: embree, OpenImageIO::OpenImageIO,
# TBB::tbb, nlohmann_json::nlohmann_json, glfw, OpenGL::GL, pathlab_imgui,
# Boost::headers (Boost.Math's distributions, header-only: the grader's and the tests' p-values
# and quantiles).
include(${CMAKE_CURRENT_LIST_DIR}/drop_missing_include_dirs.cmake)

# Embree 3 on Debian 12, Embree 4 on Debian 13, Ubuntu 24.04, Homebrew and vcpkg; embree_api.h
# hides the difference.
find_package(embree 4 QUIET)
if(NOT embree_FOUND)
    find_package(embree 3 REQUIRED)
endif()
# Embree's own tools, which the benchmark and the scene tests compare with, where Debian's and
# Ubuntu's embree-tools put them for the Embree found: Embree 4's tutorials are called embree_NAME
# (pathtracer is embree_pathtracer), and their models are in the documentation folder of Embree's
# major version (/usr/share/doc/embree4/models). The one place that knows; whether the tools are
# installed is found out where they are used, which says so when they are not.
add_library(pathlab_embree_tools INTERFACE)
if(embree_VERSION VERSION_GREATER_EQUAL 4)
    set(PATHLAB_EMBREE_PATHTRACER embree_pathtracer)
else()
    set(PATHLAB_EMBREE_PATHTRACER pathtracer)
endif()
target_compile_definitions(pathlab_embree_tools INTERFACE
    PATHLAB_EMBREE_PATHTRACER="${PATHLAB_EMBREE_PATHTRACER}"
    PATHLAB_EMBREE_MODELS_DIR="/usr/share/doc/embree${embree_VERSION_MAJOR}/models")
find_package(OpenImageIO REQUIRED)
drop_missing_include_dirs(OpenImageIO::OpenImageIO)
find_package(TBB REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(Threads REQUIRED)
find_package(glfw3 3.3 REQUIRED)
find_package(OpenGL REQUIRED)
# Boost.Math's distributions (header-only): from Boost's own BoostConfig.cmake, which Debian,
# Homebrew and vcpkg install; CMake 3.30 dropped its FindBoost module for that (policy CMP0167).
find_package(Boost 1.71 REQUIRED CONFIG)

# Dear ImGui with its GLFW and OpenGL 2 back-ends: vcpkg's package (imgui[glfw-binding,
# opengl2-binding]), Debian's libimgui-dev through pkg-config, or a source folder (Homebrew has
# no package: scripts/install-deps.sh puts a release of it in third_party/imgui).
add_library(pathlab_imgui INTERFACE)
find_package(imgui CONFIG QUIET)
set(PATHLAB_IMGUI_SOURCE ${PROJECT_SOURCE_DIR}/third_party/imgui
    CACHE PATH "A Dear ImGui source folder, used when no package provides it")
if(imgui_FOUND)
    target_link_libraries(pathlab_imgui INTERFACE imgui::imgui)
    set(PATHLAB_IMGUI_FROM "its CMake package")
else()
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
        pkg_check_modules(IMGUI QUIET IMPORTED_TARGET GLOBAL imgui)
    endif()
    if(IMGUI_FOUND)
        find_path(PATHLAB_IMGUI_BACKENDS imgui_impl_glfw.h PATHS ${IMGUI_INCLUDE_DIRS}
                  PATH_SUFFIXES backends REQUIRED)
        target_link_libraries(pathlab_imgui INTERFACE PkgConfig::IMGUI)
        target_include_directories(pathlab_imgui INTERFACE ${PATHLAB_IMGUI_BACKENDS})
        set(PATHLAB_IMGUI_FROM "pkg-config")
    elseif(EXISTS ${PATHLAB_IMGUI_SOURCE}/imgui.cpp)
        set(dir ${PATHLAB_IMGUI_SOURCE})
        add_library(pathlab_imgui_sources STATIC
            ${dir}/imgui.cpp ${dir}/imgui_draw.cpp ${dir}/imgui_tables.cpp ${dir}/imgui_widgets.cpp
            ${dir}/backends/imgui_impl_glfw.cpp ${dir}/backends/imgui_impl_opengl2.cpp)
        target_include_directories(pathlab_imgui_sources SYSTEM PUBLIC ${dir} ${dir}/backends)
        target_link_libraries(pathlab_imgui_sources PUBLIC glfw OpenGL::GL)
        target_link_libraries(pathlab_imgui INTERFACE pathlab_imgui_sources)
        set(PATHLAB_IMGUI_FROM "${dir}")
    else()
        message(FATAL_ERROR "Dear ImGui not found: apt install libimgui-dev (Debian, Ubuntu), "
                "vcpkg install \"imgui[glfw-binding,opengl2-binding]\", or a release of its "
                "sources in ${PATHLAB_IMGUI_SOURCE} (scripts/install-deps.sh does on macOS)")
    endif()
endif()
message(STATUS "Dear ImGui: from ${PATHLAB_IMGUI_FROM}")
