# Debian 12's OpenImageIO config lists /usr/include/opencv4 among its include folders even when
# OpenCV's headers are not installed, and CMake refuses a target whose include folder is missing.
# OpenImageIO's own headers do not need it: keep only the folders that exist.
function(drop_missing_include_dirs target)
    foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
        get_target_property(dirs ${target} ${property})
        if(NOT dirs)
            continue()
        endif()
        set(kept "")
        foreach(dir IN LISTS dirs)
            if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
                list(APPEND kept "${dir}")
            endif()
        endforeach()
        set_target_properties(${target} PROPERTIES ${property} "${kept}")
    endforeach()
endfunction()
