# Real-reader tests: a packing written by frontpack is read back by LAMMPS (read_data), VTK
# (vtkXMLPolyDataReader) and Yade (ymport.textExt), and every disk must come back bit-identical
# (tests/readers/check_readers.py). The programs are Debian packages that only `tools/dev.sh test`
# installs (lammps, python3-vtk9, yade): the tests are always registered; without the program a
# test is skipped (exit 77), unless FRONTPACK_REQUIRE_READERS=1 (as dev.sh test sets), where it
# fails.
#
# FRONTPACK_TEST_PROGRAMS OFF leaves these tests out (the clang preset: the programs read the same
# bytes whichever compiler built the writer, since the pinned tests hold Clang's packings to GCC's
# bits; running LAMMPS, LIGGGHTS and Yade again there only doubles their minutes in CI).
option(FRONTPACK_TEST_PROGRAMS "Test that LAMMPS, LIGGGHTS, Yade and VTK read and run what we write" ON)
add_executable(frontpack_write_formats ${CMAKE_CURRENT_LIST_DIR}/write_formats.cpp)
target_link_libraries(frontpack_write_formats PRIVATE frontpack::frontpack)
frontpack_target_settings(frontpack_write_formats)
# Reads a disk file strictly and certifies it (tool_tests.cmake: the tool's CSV reads back).
add_executable(frontpack_read_disks ${CMAKE_CURRENT_LIST_DIR}/read_disks.cpp)
target_link_libraries(frontpack_read_disks PRIVATE frontpack::frontpack)
frontpack_target_settings(frontpack_read_disks)

# Debian's Python modules (vtk from python3-vtk9) are installed for Debian's interpreter, which
# may not be the first python3 on PATH (pyenv, a virtual environment).
find_program(FRONTPACK_DEBIAN_PYTHON3 python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(FRONTPACK_PYTHON3 python3)
if(FRONTPACK_DEBIAN_PYTHON3)
  set(frontpack_reader_python ${FRONTPACK_DEBIAN_PYTHON3})
else()
  set(frontpack_reader_python ${FRONTPACK_PYTHON3})
endif()

if(FRONTPACK_TEST_PROGRAMS)
foreach(reader lammps vtk yade)
  if(frontpack_reader_python)
    add_test(NAME readers.${reader}
      COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_LIST_DIR}/check_readers.py ${reader}
              $<TARGET_FILE:frontpack_write_formats> ${PROJECT_SOURCE_DIR}/shapes/l_shape.wkt
              ${CMAKE_CURRENT_BINARY_DIR}/readers/${reader})
  else()
    # No Python at all: the same skip-or-fail rule, in the shell.
    add_test(NAME readers.${reader}
      COMMAND sh -c "echo 'python3 is not installed'; test \"$FRONTPACK_REQUIRE_READERS\" = 1 && exit 1; exit 77")
  endif()
  set_tests_properties(readers.${reader} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS readers)
endforeach()
endif()

# The other direction: files written by LAMMPS (write_data, dump) and VTK (vtkXMLPolyDataWriter)
# read back by frontpack's readers bit for bit, and `frontpack check` on them
# (tests/readers/from_programs.py). Same skip-or-fail rule as above.
add_executable(frontpack_disks_to_csv ${CMAKE_CURRENT_LIST_DIR}/disks_to_csv.cpp)
target_link_libraries(frontpack_disks_to_csv PRIVATE frontpack::frontpack)
frontpack_target_settings(frontpack_disks_to_csv)
if(FRONTPACK_BUILD_TOOLS AND FRONTPACK_TEST_PROGRAMS)
  foreach(program lammps vtk)
    if(frontpack_reader_python)
      add_test(NAME readers.from_${program}
        COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_LIST_DIR}/from_programs.py ${program}
                $<TARGET_FILE:frontpack_write_formats> $<TARGET_FILE:frontpack_disks_to_csv>
                $<TARGET_FILE:frontpack_tool> ${PROJECT_SOURCE_DIR}/shapes/l_shape.wkt
                ${CMAKE_CURRENT_BINARY_DIR}/from_programs/${program})
    else()
      add_test(NAME readers.from_${program}
        COMMAND sh -c "echo 'python3 is not installed'; test \"$FRONTPACK_REQUIRE_READERS\" = 1 && exit 1; exit 77")
    endif()
    set_tests_properties(readers.from_${program} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS readers)
  endforeach()
endif()

# Simulator decks (fill --deck): the real lmp, liggghts and yade run them as written; a free disk
# may not leave the domain, and the same deck without its walls must be seen leaking
# (tests/readers/check_decks.py). The gear, and a drum with a hole drawn in a DXF (CIRCLE entities,
# made polylines on the domain's side). Skip-or-fail as above.
if(FRONTPACK_BUILD_TOOLS AND FRONTPACK_TEST_PROGRAMS)
  set(frontpack_deck_cases lammps:shapes/gear.wkt:uniform:0.008,0.016 liggghts:shapes/gear.wkt:uniform:0.008,0.016
                           yade:shapes/gear.wkt:uniform:0.008,0.016)
  if(FRONTPACK_WITH_DXFLIB)
    list(APPEND frontpack_deck_cases lammps:tests/data/cad/drum.dxf:uniform:0.015,0.03
                                     liggghts:tests/data/cad/drum.dxf:uniform:0.015,0.03)
  endif()
  foreach(deck IN LISTS frontpack_deck_cases)
    string(REPLACE ":" ";" parts "${deck}")
    list(GET parts 0 simulator)
    list(GET parts 1 shape)
    list(GET parts 2 kind)
    list(GET parts 3 range)
    get_filename_component(stem ${shape} NAME_WE)
    set(name decks.${simulator}.${stem})
    if(frontpack_reader_python)
      add_test(NAME ${name}
        COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_LIST_DIR}/check_decks.py ${simulator}
                $<TARGET_FILE:frontpack_tool> ${PROJECT_SOURCE_DIR}/${shape} ${kind}:${range}
                ${CMAKE_CURRENT_BINARY_DIR}/decks/${simulator}_${stem})
    else()
      add_test(NAME ${name}
        COMMAND sh -c "echo 'python3 is not installed'; test \"$FRONTPACK_REQUIRE_READERS\" = 1 && exit 1; exit 77")
    endif()
    # COST: started first, so that these few-second runs overlap the many short tests.
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS readers COST 50)
  endforeach()
endif()

# Periodic cells: the LAMMPS, LIGGGHTS and Yade decks of a dense periodic packing (boundary p p p,
# and p f p for a shear cell; Yade O.periodic) run in the real programs: no contact at the start, none
# lost, the packing certified by check --periodic, and a planted overlap across the seam seen by
# the program and by the check (tests/readers/check_periodic_deck.py). Skip-or-fail as above.
add_executable(frontpack_periodic_deck ${CMAKE_CURRENT_LIST_DIR}/periodic_deck.cpp)
target_link_libraries(frontpack_periodic_deck PRIVATE frontpack::frontpack)
frontpack_target_settings(frontpack_periodic_deck)
if(FRONTPACK_BUILD_TOOLS AND FRONTPACK_TEST_PROGRAMS)
  foreach(case lammps:xy lammps:x liggghts:xy liggghts:x yade:xy yade:x)
    string(REPLACE ":" ";" parts "${case}")
    list(GET parts 0 simulator)
    list(GET parts 1 axes)
    set(name decks.${simulator}.periodic_${axes})
    if(frontpack_reader_python)
      add_test(NAME ${name}
        COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_LIST_DIR}/check_periodic_deck.py ${simulator} ${axes}
                $<TARGET_FILE:frontpack_periodic_deck> $<TARGET_FILE:frontpack_tool>
                ${CMAKE_CURRENT_BINARY_DIR}/decks/periodic_${simulator}_${axes})
    else()
      add_test(NAME ${name}
        COMMAND sh -c "echo 'python3 is not installed'; test \"$FRONTPACK_REQUIRE_READERS\" = 1 && exit 1; exit 77")
    endif()
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS readers)
  endforeach()
endif()
