# The invariants the source tree keeps (docs/architecture.md), checked on the files themselves:
#   1. Nothing under src/generate/ or src/jam/ includes CGAL, directly or through our own headers: the
#      generators are plain floating point, and exact decisions reach them only through the
#      CGAL-free facade exact/overlap.hpp.
#   2. No public header includes CGAL, except include/frontpack/cgal.hpp (opt-in interop).
#   3. No source file in src/, tools/, include/ or python/ is over 600 lines.
#   4. Source comments carry no history: no dates, no "session".
# Run: cmake -DSOURCE_DIR=<repo> -P tests/layout/check_layout.cmake
cmake_minimum_required(VERSION 3.25)

set(failures "")

# The files a file includes with "...", resolved against src/, include/ and the file's folder.
function(quoted_includes file out)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  get_filename_component(dir "${file}" DIRECTORY)
  set(found "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" name "${line}")
    foreach(root "${SOURCE_DIR}/src" "${SOURCE_DIR}/include" "${dir}")
      if(EXISTS "${root}/${name}")
        list(APPEND found "${root}/${name}")
        break()
      endif()
    endforeach()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# Sets `chain` to the include chain from `file` to a CGAL header, or "" if there is none.
function(cgal_chain file out)
  set(seen "${file}")
  set(queue "${file}")
  set(parent_of_${file} "")
  while(queue)
    list(POP_FRONT queue current)
    file(STRINGS "${current}" cgal REGEX "^[ \t]*#[ \t]*include[ \t]*<CGAL/")
    if(cgal)
      set(chain "${current}")
      set(p "${parent_of_${current}}")
      while(p)
        set(chain "${p} -> ${chain}")
        set(p "${parent_of_${p}}")
      endwhile()
      set(${out} "${chain} -> ${cgal}" PARENT_SCOPE)
      return()
    endif()
    quoted_includes("${current}" next)
    foreach(n IN LISTS next)
      if(NOT n IN_LIST seen)
        list(APPEND seen "${n}")
        list(APPEND queue "${n}")
        set(parent_of_${n} "${current}")
      endif()
    endforeach()
  endwhile()
  set(${out} "" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE generate_files "${SOURCE_DIR}/src/generate/*.hpp" "${SOURCE_DIR}/src/generate/*.cpp"
     "${SOURCE_DIR}/src/jam/*.hpp" "${SOURCE_DIR}/src/jam/*.cpp")
if(NOT generate_files)
  string(APPEND failures "  no files found under src/generate/\n")
endif()
file(GLOB public_headers "${SOURCE_DIR}/include/frontpack/*.hpp")
list(FILTER public_headers EXCLUDE REGEX "/cgal\\.hpp$")
foreach(f IN LISTS generate_files public_headers)
  cgal_chain("${f}" chain)
  if(chain)
    string(APPEND failures "  includes CGAL: ${chain}\n")
  endif()
endforeach()

file(GLOB_RECURSE sources "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/src/*.cpp" "${SOURCE_DIR}/tools/*.hpp"
     "${SOURCE_DIR}/tools/*.cpp" "${SOURCE_DIR}/include/*.hpp" "${SOURCE_DIR}/python/*.hpp"
     "${SOURCE_DIR}/python/*.cpp")
foreach(f IN LISTS sources)
  file(READ "${f}" text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines n)
  if(n GREATER 600)
    string(APPEND failures "  ${n} lines (at most 600): ${f}\n")
  endif()
  file(STRINGS "${f}" history REGEX "//.*(20[0-9][0-9]-[01][0-9]-[0-3][0-9]|[Ss]ession)")
  foreach(line IN LISTS history)
    string(APPEND failures "  history in a comment: ${f}: ${line}\n")
  endforeach()
endforeach()

if(failures)
  message(FATAL_ERROR "The source tree breaks its layout invariants (docs/architecture.md):\n${failures}")
endif()
list(LENGTH generate_files ng)
list(LENGTH public_headers nh)
list(LENGTH sources ns)
message(STATUS "layout: ${ng} files in src/generate/ and src/jam/ and ${nh} public headers CGAL-free; ${ns} sources within 600 lines")
