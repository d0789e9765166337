# The list of labs, framework/lab_list.txt: read and checked, and written out as the header the
# C++ code follows (pathlab/lab_list.h, in the build folder). The root CMakeLists.txt includes
# this file; run as a script, it checks a list and prints its labs' names, which is how
# tests/docs/lab_list_test.py shows that a bad line stops the build:
#   cmake -DPATHLAB_LAB_LIST=FILE -P cmake/lab_list.cmake
if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    # The policies the build has (CMP0007: a list keeps its empty elements, so that each line of
    # the file is one element and the line numbers are right).
    cmake_minimum_required(VERSION 3.18)
endif()

# pathlab_read_lab_list(FILE NAMES ENTRIES LOBE_ENTRIES): the labs' names, in order, into NAMES,
# their PATHLAB_LAB(name, Enumerator, depthLimited) entries for the header into ENTRIES, and a
# PATHLAB_LOBE_LAB(name, Enumerator) entry into LOBE_ENTRIES for each lab that writes a lobe. A line that is
# not a lab (a wrong number of fields, a name or enumerator that is not a C++ identifier, an
# estimate other than depth-limited or unbiased, a lab or enumerator named twice) stops CMake
# with the file, the line and what is wrong; so does a list without a lab.
function(pathlab_read_lab_list file names_var entries_var lobe_entries_var)
    # As UTF-8: read as ASCII, a line is split at each other character (in a comment, say).
    file(STRINGS ${file} lines ENCODING UTF-8)
    set(names "")
    set(entries "")
    set(lobe_entries "")
    set(number 0)
    foreach(line IN LISTS lines)
        math(EXPR number "${number} + 1")
        set(where "${file}:${number}")
        # CMake reads the lines as a list, which a ';' splits and an unmatched '[' or ']', or a
        # backslash at the end of a line, joins to the next: the element then holds a ';'.
        if(line MATCHES "[][;\\]")
            message(FATAL_ERROR "${where}: a ';', '[', ']' or '\\', which the list of labs cannot "
                                "hold, even in a comment (CMake reads the file as a list of "
                                "lines, which these split or join)")
        endif()
        string(STRIP "${line}" line)
        if(line STREQUAL "" OR line MATCHES "^#")
            continue()
        endif()
        string(REGEX MATCHALL "[^ \t]+" fields "${line}")
        list(LENGTH fields count)
        if(NOT count EQUAL 3 AND NOT count EQUAL 4)
            message(FATAL_ERROR "${where}: ${count} field(s) where a lab has 3 or 4, "
                                "`name Enumerator depth-limited|unbiased [lobe]`: ${line}")
        endif()
        set(lobe false)
        if(count EQUAL 4)
            list(GET fields 3 routines)
            if(NOT routines STREQUAL "lobe")
                message(FATAL_ERROR "${where}: the fourth field `${routines}` is not `lobe` (the "
                                    "only routines a lab may write beside pathTrace)")
            endif()
            set(lobe true)
        endif()
        list(GET fields 0 name)
        list(GET fields 1 enumerator)
        list(GET fields 2 estimate)
        foreach(identifier IN ITEMS ${name} ${enumerator})
            if(NOT identifier MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
                message(FATAL_ERROR "${where}: `${identifier}` is not a C++ identifier (letters, "
                                    "digits and _, not starting with a digit)")
            endif()
        endforeach()
        if(estimate STREQUAL "depth-limited")
            set(depth_limited true)
        elseif(estimate STREQUAL "unbiased")
            set(depth_limited false)
        else()
            message(FATAL_ERROR "${where}: the estimate `${estimate}` is neither depth-limited "
                                "nor unbiased")
        endif()
        if(DEFINED line_of_lab_${name})
            message(FATAL_ERROR "${where}: the lab `${name}` again (line ${line_of_lab_${name}})")
        endif()
        if(DEFINED line_of_enumerator_${enumerator})
            message(FATAL_ERROR "${where}: the enumerator `${enumerator}` again "
                                "(line ${line_of_enumerator_${enumerator}})")
        endif()
        set(line_of_lab_${name} ${number})
        set(line_of_enumerator_${enumerator} ${number})
        list(APPEND names ${name})
        list(APPEND entries "PATHLAB_LAB(${name}, ${enumerator}, ${depth_limited})")
        if(lobe)
            list(APPEND lobe_entries "PATHLAB_LOBE_LAB(${name}, ${enumerator})")
        endif()
    endforeach()
    if(NOT names)
        message(FATAL_ERROR "${file}: no lab in it (one line per lab: "
                            "`name Enumerator depth-limited|unbiased`)")
    endif()
    set(${names_var} ${names} PARENT_SCOPE)
    set(${entries_var} ${entries} PARENT_SCOPE)
    set(${lobe_entries_var} ${lobe_entries} PARENT_SCOPE)
endfunction()

# pathlab_lab_list(FILE HEADER NAMES): the labs of FILE, checked, their names into NAMES, and
# HEADER written from them (lab_list.h.in beside this file), rewritten only when it changes.
# CMake configures again when FILE changes.
function(pathlab_lab_list file header names_var)
    pathlab_read_lab_list(${file} names entries lobe_entries)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
    list(JOIN entries " \\\n    " PATHLAB_LAB_ENTRIES)
    list(JOIN lobe_entries " \\\n    " PATHLAB_LOBE_LAB_ENTRIES)
    configure_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/lab_list.h.in ${header} @ONLY)
    set(${names_var} ${names} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
    if(NOT PATHLAB_LAB_LIST)
        message(FATAL_ERROR "usage: cmake -DPATHLAB_LAB_LIST=FILE -P ${CMAKE_CURRENT_LIST_FILE}")
    endif()
    pathlab_read_lab_list(${PATHLAB_LAB_LIST} names entries lobe_entries)
    list(JOIN names " " names)
    message("labs: ${names}")
endif()
