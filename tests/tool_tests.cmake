# Tests of the frontpack tool: exit codes and messages (run through tests/run_tool.cmake, which
# checks the exit code and a regular expression on the combined output).
function(frontpack_tool_test name expected_exit regex)
  add_test(NAME tool.${name}
    COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:frontpack_tool> -DEXPECTED_EXIT=${expected_exit}
            "-DREGEX=${regex}" "-DARGS=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/run_tool.cmake)
endfunction()

set(S ${PROJECT_SOURCE_DIR}/shapes)
set(D ${CMAKE_CURRENT_SOURCE_DIR}/data/invalid)
frontpack_tool_test(info_concave 0 "polygons: +1.*area: +0.6875" info ${S}/concave_polygon.wkt)
frontpack_tool_test(info_islands 0 "polygons: +4.*holes: +1" info ${S}/islands.wkt)
frontpack_tool_test(info_inline_wkt 0 "area: +2" info --wkt "POLYGON((0 0,2 0,2 1,0 1,0 0))")
frontpack_tool_test(help 0 "Example:.*frontpack info shapes/concave_polygon.wkt" info --help)
frontpack_tool_test(version 0 "0\\.2\\.0" --version)
frontpack_tool_test(no_subcommand 1 "subcommand" "")
frontpack_tool_test(unknown_option 1 "--bogus" info --bogus ${S}/unit_square.wkt)
frontpack_tool_test(missing_file 2 "cannot open '/nonexistent.wkt': No such file or directory" info /nonexistent.wkt)
frontpack_tool_test(directory 2 "is a directory" info ${S})
frontpack_tool_test(wkt_syntax 3 "WKT error at line 1, column 26 .*expected ',' or '\\)'" info --wkt "POLYGON((0 0,1 0,1 1,0 0)")
frontpack_tool_test(wkt_point 3 "unsupported geometry type POINT" info --wkt "POINT(1 2)")
frontpack_tool_test(invalid_bowtie 4 "invalid domain: polygon 0, outer ring: edge 0 .* and edge 2 .* cross" info --wkt "POLYGON((0 0,1 1,1 0,0 1,0 0))")

frontpack_tool_test(fill_csv_svg 0 "disks: +[0-9]+ .*certificate: certified: [0-9]+ generated, [0-9]+ culled .*, 0 dropped"
  fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --seed 3 -o ${CMAKE_CURRENT_BINARY_DIR}/l.csv -o ${CMAKE_CURRENT_BINARY_DIR}/l.svg)
frontpack_tool_test(fill_open 0 "open form" fill ${S}/annulus.wkt --method open --radius constant:0.05)
frontpack_tool_test(fill_bad_radius 5 "rmin \\(0.2\\) must not exceed rmax \\(0.1\\)" fill ${S}/l_shape.wkt --radius uniform:0.2,0.1)
frontpack_tool_test(fill_bad_radius_syntax 5 "expected uniform:RMIN,RMAX or constant:R" fill ${S}/l_shape.wkt --radius gauss:1)
frontpack_tool_test(fill_nan_radius 5 "must be a finite number > 0" fill ${S}/l_shape.wkt --radius constant:nan)
frontpack_tool_test(fill_bad_method 5 "--method diagonal: expected closed or open" fill ${S}/l_shape.wkt --method diagonal)
frontpack_tool_test(fill_bad_format 5 "unknown format '.xyz'" fill ${S}/l_shape.wkt -o out.xyz)
frontpack_tool_test(fill_unwritable 2 "cannot write '/nonexistent/dir/p.csv.tmp'" fill ${S}/l_shape.wkt -o /nonexistent/dir/p.csv)
frontpack_tool_test(fill_too_many 5 "would generate about [0-9]+ disks, more than max_disks" fill ${S}/unit_square.wkt --radius constant:1e-5)

# The tool's CSV read back by the library's strict reader (frontpack::read_disks) and certified
# again: the file holds the certificate and as many disks as the tool reported.
set(roundtrip_csv ${CMAKE_CURRENT_BINARY_DIR}/l_roundtrip.csv)
set(roundtrip_args fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --seed 3 -o ${roundtrip_csv})
add_test(NAME tool.fill_csv_reads_back
  COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:frontpack_tool> -DREADER=$<TARGET_FILE:frontpack_read_disks>
          -DSHAPE=${S}/l_shape.wkt -DOUTPUT=${roundtrip_csv} "-DARGS=${roundtrip_args}"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/readers/tool_roundtrip.cmake)
