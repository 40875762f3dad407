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
string(REPLACE "." "\\." _version_regex "${PROJECT_VERSION}")
frontpack_tool_test(version 0 "^${_version_regex}" --version)
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
frontpack_tool_test(fill_boundary 0 "boundary form.*certified: [0-9]+ generated, 0 culled .*, 0 dropped"
  fill ${S}/plate_with_holes.wkt --method boundary --radius uniform:0.01,0.1 --seed 2)
frontpack_tool_test(fill_bad_radius 5 "rmin \\(0.2\\) must not exceed rmax \\(0.1\\)" fill ${S}/l_shape.wkt --radius uniform:0.2,0.1)
frontpack_tool_test(fill_bad_radius_syntax 5 "expected uniform:RMIN,RMAX or constant:R" fill ${S}/l_shape.wkt --radius gauss:1)
frontpack_tool_test(fill_nan_radius 5 "must be a finite number > 0" fill ${S}/l_shape.wkt --radius constant:nan)
frontpack_tool_test(fill_bad_method 5 "--method 'diagonal': expected closed, open or boundary" fill ${S}/l_shape.wkt --method diagonal)
frontpack_tool_test(fill_bad_format 5 "unknown format '.xyz'" fill ${S}/l_shape.wkt -o out.xyz)
frontpack_tool_test(fill_unwritable 2 "cannot write '/nonexistent/dir/p.csv': No such file or directory" fill ${S}/l_shape.wkt -o /nonexistent/dir/p.csv)
frontpack_tool_test(fill_too_many 5 "would make about [0-9]+ disks, more than max_disks" fill ${S}/unit_square.wkt --radius constant:1e-5)

# The tool's CSV read back by the library's strict reader (frontpack::read_disks) and certified
# again: the file holds the certificate and as many disks as the tool reported.
set(roundtrip_csv ${CMAKE_CURRENT_BINARY_DIR}/l_roundtrip.csv)
set(roundtrip_args fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --seed 3 -o ${roundtrip_csv})
add_test(NAME tool.fill_csv_reads_back
  COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:frontpack_tool> -DREADER=$<TARGET_FILE:frontpack_read_disks>
          -DSHAPE=${S}/l_shape.wkt -DOUTPUT=${roundtrip_csv} "-DARGS=${roundtrip_args}"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/readers/tool_roundtrip.cmake)

# Tests with checks on the files a run writes (see run_tool.cmake): each writes into its own
# directory under tool_out/, which must be free of temporary files afterwards.
#   frontpack_tool_check(NAME EXIT REGEX [SILENT] [FILES f...] [NO_FILES f...] [PNG f w h]
#                        [JSON f key=regex...] [FILE_MATCHES f regex] ARGS arg...)
function(frontpack_tool_check name expected_exit regex)
  cmake_parse_arguments(T "SILENT" "" "FILES;NO_FILES;PNG;JSON;FILE_MATCHES;ARGS" ${ARGN})
  add_test(NAME tool.${name}
    COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:frontpack_tool> -DEXPECTED_EXIT=${expected_exit}
            "-DREGEX=${regex}" "-DARGS=${T_ARGS}" -DOUT_DIR=${TOOL_OUT}/${name} "-DFILES=${T_FILES}"
            "-DNO_FILES=${T_NO_FILES}" "-DPNG=${T_PNG}" "-DJSON=${T_JSON}" "-DFILE_MATCHES=${T_FILE_MATCHES}"
            -DSILENT=${T_SILENT}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/run_tool.cmake)
endfunction()

# The height of the pictures' size-distribution panel for a width, computed as tools/render.cpp's
# histogram_height does: width / 4 + 6 font sizes, the font size width / 80 clamped to [10, 18].
function(frontpack_histogram_height width out)
  math(EXPR font "${width} / 80")
  if(font LESS 10)
    set(font 10)
  elseif(font GREATER 18)
    set(font 18)
  endif()
  math(EXPR height "${width} / 4 + 6 * ${font}")
  set(${out} ${height} PARENT_SCOPE)
endfunction()

set(TD ${CMAKE_CURRENT_SOURCE_DIR}/data/tool)
set(TOOL_OUT ${CMAKE_CURRENT_BINARY_DIR}/tool_out)
set(SQ ${S}/unit_square.wkt)

# fill: every format, the JSON summary, --quiet. The plate at 401 px is 209 px high, plus the panel.
frontpack_histogram_height(401 panel_401)
math(EXPR plate_401_height "209 + ${panel_401}")
set(O ${TOOL_OUT}/fill_all_formats)
frontpack_tool_check(fill_all_formats 0
  "fraction: +0\\.[0-9]+ overall, 0\\.[0-9]+ interior.*radii: +min .*wrote: .*p\\.data \\(lammps\\).*p\\.png \\(png\\)"
  FILES ${O}/p.csv ${O}/p.txt ${O}/p.data ${O}/p.vtp ${O}/p.svg ${O}/p.pdf ${O}/p.png ${O}/s.json
  PNG ${O}/p.png 401 ${plate_401_height}
  JSON ${O}/s.json "command=^fill$" "method=^boundary$" "seed=^7$" "disks=^[1-9][0-9]+$"
       "packing_fraction=^0\\.[6-9]" "interior_fraction=^0\\.[6-9]" "radius/min=^0\\.0" "radius/mean=^0\\.0"
       "certificate/certified=^ON$" "certificate/culled=^0$" "certificate/dropped=^0$" "certificate/exact=^ON$" "domain/holes=^7$"
       "seconds/total=^[0-9]" "outputs/6/format=^png$" "generation/skipped_radii=^[0-9]+$" "generation/cavities=^[0-9]+$" "generation/attempts=^[1-9]"
  ARGS fill ${S}/plate_with_holes.wkt --radius uniform:0.01,0.04 --seed 7 --width 401 -o ${O}/p.csv -o ${O}/p.txt
       -o ${O}/p.data -o ${O}/p.vtp -o ${O}/p.svg -o ${O}/p.pdf -o ${O}/p.png --json ${O}/s.json)
set(O ${TOOL_OUT}/fill_no_histogram)
frontpack_tool_check(fill_no_histogram 0 "wrote: .*p\\.png \\(png\\)" PNG ${O}/p.png 401 209
  ARGS fill ${S}/plate_with_holes.wkt --radius uniform:0.01,0.04 --seed 7 --width 401 --no-histogram -o ${O}/p.png)
set(O ${TOOL_OUT}/fill_quiet)
frontpack_tool_check(fill_quiet 0 "" SILENT FILES ${O}/q.csv ${O}/q.json
  ARGS fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --quiet -o ${O}/q.csv --json ${O}/q.json)
set(O ${TOOL_OUT}/fill_format_option)
frontpack_tool_check(fill_format_option 0 "wrote: .*out\\.dat \\(yade\\)" FILES ${O}/out.dat
  ARGS fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --format yade -o ${O}/out.dat)
frontpack_tool_check(fill_unknown_format_option 5 "--format 'bogus': unknown format; expected csv, yade, lammps, vtp, png, svg or pdf"
  NO_FILES ${TOOL_OUT}/fill_unknown_format_option/p.csv
  ARGS fill ${S}/l_shape.wkt --format bogus -o ${TOOL_OUT}/fill_unknown_format_option/p.csv)
frontpack_tool_check(fill_no_extension 5 "no file extension to tell the format by"
  ARGS fill ${S}/l_shape.wkt -o ${TOOL_OUT}/fill_no_extension/packing)
# A bad second output fails before anything is written: no partial set of outputs either.
frontpack_tool_check(fill_unwritable_second 2 "cannot write '/nonexistent/dir/p\\.csv'"
  NO_FILES ${TOOL_OUT}/fill_unwritable_second/first.csv
  ARGS fill ${S}/l_shape.wkt -o ${TOOL_OUT}/fill_unwritable_second/first.csv -o /nonexistent/dir/p.csv)
frontpack_tool_check(fill_zero_radius 5 "radius 'constant:0': .*must be a finite number > 0"
  NO_FILES ${TOOL_OUT}/fill_zero_radius/p.csv ARGS fill ${S}/l_shape.wkt --radius constant:0 -o ${TOOL_OUT}/fill_zero_radius/p.csv)
frontpack_tool_check(fill_negative_radius 5 "radius 'uniform:-0.1,0.1'" ARGS fill ${S}/l_shape.wkt --radius uniform:-0.1,0.1)
frontpack_tool_check(fill_nan_uniform 5 "radius 'uniform:nan,0.1'" ARGS fill ${S}/l_shape.wkt --radius uniform:nan,0.1)
frontpack_tool_check(fill_missing_domain 2 "cannot open '/nonexistent/domain.wkt'"
  NO_FILES ${TOOL_OUT}/fill_missing_domain/p.csv ARGS fill /nonexistent/domain.wkt -o ${TOOL_OUT}/fill_missing_domain/p.csv)
frontpack_tool_check(fill_invalid_domain 4 "invalid domain: polygon 0, outer ring: edge 0 .* cross"
  NO_FILES ${TOOL_OUT}/fill_invalid_domain/p.csv
  ARGS fill --wkt "POLYGON((0 0,1 1,1 0,0 1,0 0))" -o ${TOOL_OUT}/fill_invalid_domain/p.csv)
frontpack_tool_check(fill_missing_domain_argument 1 "DOMAIN or --wkt" ARGS fill --radius constant:0.1)
frontpack_tool_check(fill_unknown_option 1 "--colour" ARGS fill ${SQ} --colour red)
frontpack_tool_check(fill_help 0 "Example:.*frontpack fill shapes/plate_with_holes.wkt.*--json summary.json" ARGS fill --help)
frontpack_tool_check(help_exit_codes 0 "6 packing not certified.*7 malformed disk file.*8 no disk fits.*9 stopped.*130/143/129" ARGS --help)

# check: exact certification of hand-made files.
frontpack_tool_check(check_good 0 "disks: +5 .*outside: +0 disks.*overlaps: +0 pairs.*result: +certified"
  ARGS check ${SQ} ${TD}/good.csv)
frontpack_tool_check(check_good_yade 0 "disks: +3 .*result: +certified" ARGS check ${SQ} ${TD}/good.txt)
frontpack_tool_check(check_one_overlap 6
  "overlaps: +1 pair of overlapping disks\\; worst: disks 2 and 5 overlap by about 0\\.0625 .*NOT certified.*1 overlapping pair, 0 disks outside"
  ARGS check ${SQ} ${TD}/one_overlap.csv)
frontpack_tool_check(check_one_overlap_all 6 "overlap 2 5 .*result: +NOT certified" ARGS check --all ${SQ} ${TD}/one_overlap.csv)
frontpack_tool_check(check_outside 6
  "outside: +2 disks not entirely inside the domain\\; worst: disk 6 \\(centre \\(0\\.5, 0\\.9375\\), radius 0\\.125\\) reaches about 0\\.0625 out"
  ARGS check ${SQ} ${TD}/outside.csv)
set(O ${TOOL_OUT}/check_json)
frontpack_tool_check(check_json 6 "NOT certified" FILES ${O}/c.json
  JSON ${O}/c.json "certified=^OFF$" "overlapping_pairs=^1$" "deepest_overlap/disks/0=^2$" "deepest_overlap/disks/1=^5$"
       "deepest_overlap/depth=^0\\.0625$"
  ARGS check ${SQ} ${TD}/one_overlap.csv --json ${O}/c.json)
frontpack_tool_check(check_quiet 6 "^frontpack: .*one_overlap\\.csv is not certified" ARGS check -q ${SQ} ${TD}/one_overlap.csv)
frontpack_tool_check(check_malformed_line 7 "malformed_line\\.csv:4: expected 3 comma-separated numbers, got '0\\.75,0\\.75'"
  ARGS check ${SQ} ${TD}/malformed_line.csv)
frontpack_tool_check(check_missing_disk_file 2 "cannot open '/nonexistent/disks\\.csv'" ARGS check ${SQ} /nonexistent/disks.csv)
frontpack_tool_check(check_missing_argument 1 "DISKS is required" ARGS check ${SQ})
frontpack_tool_check(check_help 0 "Example:.*frontpack check shapes/l_shape.wkt packing.csv" ARGS check --help)

# check, stats and render read LAMMPS data and dump files and VTK PolyData, and take --wkt.
set(SQ_WKT "POLYGON((0 0,1 0,1 1,0 1,0 0))")
frontpack_tool_check(check_lammps_data 6
  "disks: +6 in .*one_overlap\\.data \\(numbered from 0 in atom id order\\).*worst: disks 2 and 5 overlap by about 0\\.0625.*overlap 2 5"
  ARGS check --all ${SQ} ${TD}/one_overlap.data)
frontpack_tool_check(check_wkt_lammps_data 6 "domain: +--wkt \\(area 1\\).*1 overlapping pair"
  ARGS check --wkt ${SQ_WKT} ${TD}/one_overlap.data)
frontpack_tool_check(check_dump_last 6 "disks: +6 .*worst: disks 2 and 5" ARGS check ${SQ} ${TD}/two_snapshots.dump)
frontpack_tool_check(check_dump_timestep 0 "disks: +5 .*result: +certified"
  ARGS check --timestep 0 ${SQ} ${TD}/two_snapshots.dump)
frontpack_tool_check(check_dump_no_timestep 7
  "two_snapshots\\.dump:29: no snapshot of timestep 7 \\(the dump has 2 snapshots: timesteps 0, 100\\)"
  ARGS check --timestep 7 ${SQ} ${TD}/two_snapshots.dump)
frontpack_tool_check(check_bad_timestep 5 "--timestep '1\\.5': expected a whole number" ARGS check --timestep 1.5 ${SQ} ${TD}/two_snapshots.dump)
frontpack_tool_check(check_vtp_wkt 0 "disks: +5 .*result: +certified" ARGS check --wkt ${SQ_WKT} ${TD}/good.vtp)
frontpack_tool_check(check_vtp_radius_array 7 "good\\.vtp:4: <Piece>: no point data array 'size' for the radii \\(point data arrays: 'Radius'\\)"
  ARGS check ${SQ} ${TD}/good.vtp --radius-array size)
frontpack_tool_check(check_vtp_compressed 7
  "compressed\\.vtp:11: <DataArray Name='Points'>: compressed data \\(vtkZLibDataCompressor\\) is not read by frontpack"
  ARGS check ${SQ} ${TD}/compressed.vtp)
frontpack_tool_check(check_lammps_nonzero_z 7 "nonzero_z\\.data:13:21: z must be 0 \\(frontpack's disks are planar\\), got '0\\.0625'"
  ARGS check ${SQ} ${TD}/nonzero_z.data)
frontpack_tool_check(check_disks_format 7 "one_overlap\\.data:1: expected an 'ITEM: \\.\\.\\.' line"
  ARGS check ${SQ} ${TD}/one_overlap.data --disks-format lammps-dump)
frontpack_tool_check(check_unknown_disks_format 5 "unknown disk file format 'xyz'; expected csv, yade, lammps, lammps-dump or vtp"
  ARGS check ${SQ} ${TD}/good.csv --disks-format xyz)
frontpack_tool_check(check_unknown_extension 5 "unknown disk file format '\\.svg'; frontpack reads \\.csv"
  ARGS check ${SQ} ${TD}/good.svg)
frontpack_tool_check(check_wkt_two_files 1 "with --wkt, give only DISKS"
  ARGS check --wkt ${SQ_WKT} ${SQ} ${TD}/good.csv)
frontpack_tool_check(check_wkt_no_disks 1 "DISKS is required" ARGS check --wkt ${SQ_WKT})
frontpack_tool_check(stats_wkt_vtp 0 "disks: +5 in .*good\\.vtp.*fraction: +0\\.2454"
  ARGS stats --wkt ${SQ_WKT} ${TD}/good.vtp --samples 10000)
frontpack_tool_check(stats_dump 0 "disks: +5 " ARGS stats ${SQ} ${TD}/two_snapshots.dump --timestep 0 --samples 10000)
set(O ${TOOL_OUT}/render_wkt_lammps)
frontpack_tool_check(render_wkt_lammps 0 "wrote: .*u\\.png \\(png, 300 x 300, 6 disks\\)" PNG ${O}/u.png 300 300
  ARGS render --wkt ${SQ_WKT} ${TD}/one_overlap.data -o ${O}/u.png --width 300 --no-histogram)

# render: PNG of the right size (the unit square at 300 px: 300 x 300, plus the panel unless
# --no-histogram), SVG, PDF.
frontpack_histogram_height(300 panel_300)
math(EXPR square_300_height "300 + ${panel_300}")
set(O ${TOOL_OUT}/render_png)
frontpack_tool_check(render_png 0 "wrote: .*u\\.png \\(png, 300 x ${square_300_height}, 5 disks\\)"
  PNG ${O}/u.png 300 ${square_300_height} ARGS render ${SQ} ${TD}/good.csv -o ${O}/u.png --width 300)
set(O ${TOOL_OUT}/render_png_no_histogram)
frontpack_tool_check(render_png_no_histogram 0 "wrote: .*u\\.png \\(png, 300 x 300, 5 disks\\)" PNG ${O}/u.png 300 300
  ARGS render ${SQ} ${TD}/good.csv -o ${O}/u.png --width 300 --no-histogram)
# Cairo draws text as glyph outlines; the caption is also the SVG's <title>.
set(O ${TOOL_OUT}/render_svg_caption)
frontpack_tool_check(render_svg_caption 0 "u\\.svg \\(svg"
  FILE_MATCHES ${O}/u.svg "<title>frontpack packing\\. Disk area per radius bin \\(5 disks, [^<]*KS by area 0\\.[0-9]+ \\(requested: uniform:0\\.1,0\\.15\\)</title>"
  ARGS render ${SQ} ${TD}/good.csv --radius uniform:0.1,0.15 -o ${O}/u.svg)
frontpack_tool_check(render_bad_radius 5 "radius 'bogus': expected uniform:RMIN,RMAX or constant:R"
  NO_FILES ${TOOL_OUT}/render_bad_radius/u.png
  ARGS render ${SQ} ${TD}/good.csv --radius bogus -o ${TOOL_OUT}/render_bad_radius/u.png)
set(O ${TOOL_OUT}/render_svg_pdf)
frontpack_tool_check(render_svg_pdf 0 "u\\.svg \\(svg.*u\\.pdf \\(pdf" FILES ${O}/u.svg ${O}/u.pdf
  ARGS render ${SQ} ${TD}/good.csv -o ${O}/u.svg -o ${O}/u.pdf)
frontpack_tool_check(render_unknown_format 5 "unknown picture format '\\.gif'"
  NO_FILES ${TOOL_OUT}/render_unknown_format/u.gif ARGS render ${SQ} ${TD}/good.csv -o ${TOOL_OUT}/render_unknown_format/u.gif)
frontpack_tool_check(render_bad_width 5 "--width 3: expected 16 to 16384 pixels"
  NO_FILES ${TOOL_OUT}/render_bad_width/u.png ARGS render ${SQ} ${TD}/good.csv --width 3 -o ${TOOL_OUT}/render_bad_width/u.png)
frontpack_tool_check(render_malformed 7 "malformed_line\\.csv:4:"
  NO_FILES ${TOOL_OUT}/render_malformed/u.png ARGS render ${SQ} ${TD}/malformed_line.csv -o ${TOOL_OUT}/render_malformed/u.png)
frontpack_tool_check(render_unwritable 2 "cannot write '/nonexistent/dir/u\\.png'" ARGS render ${SQ} ${TD}/good.csv -o /nonexistent/dir/u.png)
# Disks far larger than the picture, or far outside it: Cairo drew their whole arcs (radius 1e308:
# past 60 s; 1e20: 15 s). Only the part inside the picture is drawn now: well under a second
# (the time limit leaves room for the sanitizer build and a busy machine).
set(O ${TOOL_OUT}/render_huge_radii)
frontpack_tool_check(render_huge_radii 0 "u\\.png \\(png, 300 x ${square_300_height}, 11 disks\\).*u\\.svg.*u\\.pdf"
  PNG ${O}/u.png 300 ${square_300_height} FILES ${O}/u.svg ${O}/u.pdf
  ARGS render ${SQ} ${TD}/huge_radii.csv -o ${O}/u.png -o ${O}/u.svg -o ${O}/u.pdf --width 300 --radius uniform:0.1,1e308)
set_tests_properties(tool.render_huge_radii PROPERTIES TIMEOUT 20)
# A domain 4e-320 wide has no finite pixels per unit (it was refused as "taller than 32767
# pixels"): drawn at a scaled unit, like any other.
set(O ${TOOL_OUT}/render_subnormal_domain)
frontpack_tool_check(render_subnormal_domain 0 "u\\.png \\(png, 300 x ${square_300_height}, 2 disks\\)"
  PNG ${O}/u.png 300 ${square_300_height} ARGS render ${TD}/subnormal_square.wkt ${TD}/subnormal_disks.csv -o ${O}/u.png --width 300)
frontpack_tool_check(stats_huge_radii 0 "disks: +11 .*radii: +min 1e-05, .*max 1e\\+308"
  ARGS stats ${SQ} ${TD}/huge_radii.csv --samples 10000)
frontpack_tool_check(check_huge_radii 6 "outside: +6 disks .*overlaps: "
  ARGS check ${SQ} ${TD}/huge_radii.csv)
frontpack_tool_check(render_help 0 "Example:.*frontpack render shapes/plate_with_holes.wkt packing.csv -o packing.png" ARGS render --help)

# stats: the statistics module on a hand-made file.
set(O ${TOOL_OUT}/stats_json)
frontpack_tool_check(stats_json 0 "disks: +5 .*fraction: +0\\.2454 overall.*requested: +constant" FILES ${O}/s.json
  JSON ${O}/s.json "command=^stats$" "disks=^5$" "radius/max=^0\\.125$" "packing_fraction=^0\\.245"
  ARGS stats ${SQ} ${TD}/good.csv --radius constant:0.125 --json ${O}/s.json)
# fill --json carries the measures of holes and seams too.
set(O ${TOOL_OUT}/fill_json_voids)
frontpack_tool_check(fill_json_voids 0 "disks: +[1-9][0-9]+" FILES ${O}/s.json
  JSON ${O}/s.json "largest_empty_circle/radius_over_rmax=^[0-9]" "holes/1/count=^[0-9]+$" "coverage_profile/6/to=^$"
       "coverage_profile/5/to_rmax=^6(\\.0)?$" "cell_coverage/cell_side=^0\\.[0-9]+" "cell_coverage/cells=^[1-9]"
  ARGS fill ${SQ} --radius uniform:0.01,0.02 --seed 3 --holes --json ${O}/s.json)
# stats: the measures of holes and seams, and --hole-radius (repeatable).
set(O ${TOOL_OUT}/stats_voids)
frontpack_tool_check(stats_voids 0
  "empty circle: radius 0\\.[0-9]+ \\(<= 0\\.[0-9]+\\).*holes: +[1-9][0-9]* taking radius 0\\.1, [0-9]+ taking radius 0\\.3.*profile: +0\\.[0-9]+ at 0-1, "
  FILES ${O}/s.json
  JSON ${O}/s.json "largest_empty_circle/radius=^0\\.[0-9]+" "largest_empty_circle/radius_upper=^0\\.[0-9]+"
       "largest_empty_circle/x=^0\\.[0-9]+" "largest_empty_circle/y=^0\\.[0-9]+"
       "largest_empty_circle/radius_over_rmax=^[0-9]" "holes/0/radius=^0\\.1" "holes/0/count=^[1-9][0-9]*$"
       "holes/1/radius=^0\\.(3|29999)" "holes/1/count=^[0-9]+$" "coverage_profile/0/from=^0(\\.0)?$" "coverage_profile/0/to=^0\\.125$"
       "coverage_profile/0/from_rmax=^0(\\.0)?$" "coverage_profile/0/to_rmax=^1(\\.0)?$" "coverage_profile/0/fraction=^0\\."
       "coverage_profile/0/error=^[0-9]" "coverage_profile/0/samples=^[1-9][0-9]*$" "coverage_profile/6/from_rmax=^6(\\.0)?$"
       "coverage_profile/6/to=^$" "coverage_profile/6/to_rmax=^$" "cell_coverage/cell_side=^1(\\.0)?$" "cell_coverage/cells=^0$"
       "cell_coverage/p1=^0(\\.0)?$" "cell_coverage/p5=^0(\\.0)?$" "cell_coverage/p50=^0(\\.0)?$" "cell_coverage/sd=^0(\\.0)?$"
       "cell_coverage/nx=^1$" "cell_coverage/ny=^1$" "cell_coverage/map/0=^$"
  ARGS stats ${SQ} ${TD}/good.csv --hole-radius 0.1 --hole-radius 0.3 --json ${O}/s.json)
frontpack_tool_check(stats_bad_hole_radius 5 "--hole-radius '-1': expected a finite number > 0"
  ARGS stats ${SQ} ${TD}/good.csv --hole-radius=-1)
# stats: the hole probes a radius needs (about 20 per cell and level down to rho / 32) are estimated
# before they are made and held to --max-disks and --memory-limit (--hole-radius 1e-6 once ran
# past 30 s at 4 GB); a radius within the budget still counts.
frontpack_tool_check(stats_hole_probes_budget 5
  "would make about [0-9.e+]+ hole probes, more than max_disks = 50000000; use a larger hole radius \\(--hole-radius\\)"
  ARGS stats ${SQ} ${TD}/good.csv --hole-radius 1e-6)
frontpack_tool_check(stats_hole_probes_memory 5
  "would make about [0-9.e+]+ hole probes, needing about [0-9.e+]+ bytes of memory, more than the limit of 1048576 bytes"
  ARGS stats ${SQ} ${TD}/good.csv --hole-radius 1e-4 --memory-limit 1M)
# stats: the coverage cells and a periodic cell's images are estimated before they are made and
# held to the same budget (a cell side of 1e-5 left the coverage out without a word).
frontpack_tool_check(stats_coverage_cells_budget 5
  "about 10000000000 coverage cells, more than max_disks = 50000000; use a larger cell side \\(--cell-side\\)"
  ARGS stats ${SQ} ${TD}/good.csv --cell-side 1e-5)
frontpack_tool_check(stats_periodic_images_budget 5
  "about 40602 periodic images, more than max_disks = 10000; use a larger periodic cell"
  ARGS stats --periodic 1,1 ${TD}/one_disk.csv --cell-side 100 --samples 1000 --max-disks 10000)
frontpack_tool_check(stats_hole_probes_within 0 "holes: +[1-9][0-9]* taking radius 0\\.001"
  ARGS stats ${SQ} ${TD}/good.csv --hole-radius 1e-3 --samples 10000)
# stats --contact-gap: two disks 2^-20 apart touch for a gap of 2^-19, not for the default 1e-9 rmax.
frontpack_tool_check(stats_contact_gap_default 0 " 0 contacts, 0 wall contacts, 2 rattlers \\(gap <= 1\\.25e-10 "
  ARGS stats ${SQ} ${TD}/near_contact.csv)
set(O ${TOOL_OUT}/stats_contact_gap)
frontpack_tool_check(stats_contact_gap 0 " 1 contacts, 0 wall contacts, 2 rattlers \\(gap <= 1\\.90734863[0-9]*e-06 "
  FILES ${O}/s.json JSON ${O}/s.json "contacts=^1$" "contact_gap=^1\\.9073486328125e-06$"
  ARGS stats ${SQ} ${TD}/near_contact.csv --contact-gap 1.9073486328125e-06 --json ${O}/s.json)
frontpack_tool_check(stats_bad_contact_gap 5 "--contact-gap '0': expected a finite number > 0"
  ARGS stats ${SQ} ${TD}/near_contact.csv --contact-gap 0)
frontpack_tool_check(stats_malformed 7 "malformed_line\\.csv:4:" ARGS stats ${SQ} ${TD}/malformed_line.csv)

# stats --periodic: a periodic fill (the closed form) measured as a torus. No walls, so no band
# (null figures), no wall contact, every sample in the profile's last bin, and all 7 x 7 squares
# of 8 rmax (0.32) kept; the seam's squares (docs/periodic.md) make the 1st percentile 0.69.
set(O ${TOOL_OUT}/stats_periodic_fill)
frontpack_tool_check(stats_periodic_fill 0 "certified: [0-9]+ generated, 0 culled" FILES ${O}/p.csv
  ARGS fill --periodic 2,2 --radius uniform:0.02,0.04 --seed 1 --method closed -o ${O}/p.csv)
set_tests_properties(tool.stats_periodic_fill PROPERTIES FIXTURES_SETUP periodic_fill_csv)
frontpack_tool_check(stats_periodic 0
  "fraction: +0\\.8[0-9]+ overall, 0\\.8[0-9]+ interior \\(\\+/- 0\\.[0-9]+, no walls\\).*, 0 wall contacts, "
  FILES ${TOOL_OUT}/stats_periodic/s.json
  JSON ${TOOL_OUT}/stats_periodic/s.json "domain/periodicity=^xy$" "walls=^OFF$" "band_fraction=^$"
       "band_fraction_error=^$" "band_median_by_area=^$" "segregation_ks_by_area=^$" "band_disks=^0$"
       "wall_contacts=^0$" "interior_fraction=^0\\.8" "mean_coordination=^[34]\\." "rattlers=^[0-9]+$"
       "coverage_profile/0/samples=^0$" "coverage_profile/5/samples=^0$" "coverage_profile/6/samples=^[1-9][0-9]+$"
       "cell_coverage/cells=^49$" "cell_coverage/p1=^0\\.[678]" "cell_coverage/p50=^0\\.8" "cell_coverage/nx=^7$"
       "cell_coverage/ny=^7$" "cell_coverage/origin/0=^0(\\.0)?$" "cell_coverage/map/0=^0\\.[678]" "cell_coverage/map/48=^0\\.[678]"
       "largest_empty_circle/radius_over_rmax=^0\\."
       "holes/0/radius=^0\\.0[234]"
  ARGS stats --periodic 2,2 ${TOOL_OUT}/stats_periodic_fill/p.csv --json ${TOOL_OUT}/stats_periodic/s.json)
set_tests_properties(tool.stats_periodic PROPERTIES FIXTURES_REQUIRED periodic_fill_csv)
# stats --cell-side: cells of 0.64 (16 rmax: the radii reach nearly 0.04) on the 2 x 2 torus, 4 x 4 of them.
frontpack_tool_check(stats_cell_side 0 "cells: +16 interior cells of side 0\\.64 \\(16[.0-9]* rmax\\)"
  ARGS stats --periodic 2,2 ${TOOL_OUT}/stats_periodic_fill/p.csv --cell-side 0.64)
set_tests_properties(tool.stats_cell_side PROPERTIES FIXTURES_REQUIRED periodic_fill_csv)
# render --cells: the map instead of the disks, without the panel; its range in the SVG's title
# (the torus: 7 x 7 cells); five disks in the unit square leave no interior cell.
set(O ${TOOL_OUT}/render_cells)
frontpack_tool_check(render_cells 0 "u\\.svg \\(svg, 300 x 300, [0-9]+ disks, 49 interior cells of side 0\\.3[0-9]*, coverage 0\\.[0-9]+ \\(dark\\) to 0\\.[0-9]+ \\(light\\)\\)"
  FILE_MATCHES ${O}/u.svg "<title>frontpack cell coverage: 49 interior cells of side 0\\.3[0-9]*, coverage 0\\.[0-9]+ \\(dark\\) to 0\\.[0-9]+ \\(light\\)</title>"
  ARGS render --periodic 2,2 ${TOOL_OUT}/stats_periodic_fill/p.csv --cells -o ${O}/u.svg --width 300)
set_tests_properties(tool.render_cells PROPERTIES FIXTURES_REQUIRED periodic_fill_csv)
set(O ${TOOL_OUT}/render_cells_none)
frontpack_tool_check(render_cells_none 0 "wrote: .*u\\.png \\(png, 300 x 300, 5 disks, no interior cell\\)" PNG ${O}/u.png 300 300
  ARGS render ${SQ} ${TD}/good.csv --cells -o ${O}/u.png --width 300)
# render --cells-range: the scale's ends fixed (the torus's cells lie between them), the cells' own
# least and largest after them; refused out of order, with a word for a number, or without --cells,
# and then no picture.
set(O ${TOOL_OUT}/render_cells_range)
frontpack_tool_check(render_cells_range 0 "coverage 0\\.6000 \\(dark\\) to 0\\.9500 \\(light\\), the cells' 0\\.[6-9][0-9]+ to 0\\.[6-9][0-9]+\\)"
  FILE_MATCHES ${O}/u.svg "<title>frontpack cell coverage: 49 interior cells of side 0\\.3[0-9]*, coverage 0\\.6000 \\(dark\\) to 0\\.9500 \\(light\\), the cells' 0\\.[6-9][0-9]+ to 0\\.[6-9][0-9]+</title>"
  ARGS render --periodic 2,2 ${TOOL_OUT}/stats_periodic_fill/p.csv --cells --cells-range 0.6,0.95 -o ${O}/u.svg --width 300)
set_tests_properties(tool.render_cells_range PROPERTIES FIXTURES_REQUIRED periodic_fill_csv)
set(O ${TOOL_OUT}/render_cells_range_order)
frontpack_tool_check(render_cells_range_order 5 "--cells-range '0\\.9,0\\.8': expected LO,HI with LO < HI" NO_FILES ${O}/a.png
  ARGS render ${SQ} ${TD}/good.csv --cells --cells-range 0.9,0.8 -o ${O}/a.png)
set(O ${TOOL_OUT}/render_cells_range_number)
frontpack_tool_check(render_cells_range_number 5 "--cells-range '0\\.7,abc': 'abc' is not a finite number; expected LO,HI"
  NO_FILES ${O}/a.png ARGS render ${SQ} ${TD}/good.csv --cells --cells-range 0.7,abc -o ${O}/a.png)
set(O ${TOOL_OUT}/render_cells_range_needs_cells)
frontpack_tool_check(render_cells_range_needs_cells 1 "--cells-range requires --cells" NO_FILES ${O}/a.png
  ARGS render ${SQ} ${TD}/good.csv --cells-range 0.7,0.8 -o ${O}/a.png)
frontpack_tool_check(stats_bad_cell_side 5 "--cell-side '-0\\.5': expected a finite number > 0"
  ARGS stats ${SQ} ${TD}/good.csv --cell-side=-0.5)
frontpack_tool_check(fill_json_unwritable 2 "cannot write '/nonexistent/dir/s\\.json'"
  NO_FILES ${TOOL_OUT}/fill_json_unwritable/p.csv
  ARGS fill ${S}/l_shape.wkt -o ${TOOL_OUT}/fill_json_unwritable/p.csv --json /nonexistent/dir/s.json)

# Extreme numbers (issue #27). A domain whose area and whose disk-count estimate underflow (the
# estimate was 0 / 0, which passed both limits and reached a reserve(): exit 70) packs as at unit
# scale with every method; one where every coordinate is subnormal is refused, saying why. (Radii
# up to the largest double, which gave the boundary method exit 70, leave no disk:
# Hostile.RadiiNearTheLargestDoubleGiveAnEmptyPacking.)
foreach(m closed open boundary)
  frontpack_tool_test(fill_underflowing_area_${m} 0
    "disks: +[1-9][0-9]* .*fraction: +0\\.[5-8].*certificate: certified: [0-9]+ generated, [0-9]+ culled .*, 0 dropped"
    fill --wkt "POLYGON((0 0,1e-300 0,1e-300 1e-300,0 1e-300,0 0))" --radius constant:1e-301 --method ${m})
endforeach()
frontpack_tool_test(fill_subnormal_domain 5 "the domain and the radii are too small"
  fill --wkt "POLYGON((0 0,4e-320 0,4e-320 4e-320,0 4e-320,0 0))" --radius constant:1e-321)

# One rule for numbers out of the range of doubles, with the same words in every reader; the
# offending text quoted escaped and cut to 40 characters (issue #27).
frontpack_tool_test(wkt_underflow 3 "number '1e-400' is out of the range of a double \\(underflows to 0\\)"
  info --wkt "POLYGON((0 0,1 0,1 1,1e-400 1,0 0))")
frontpack_tool_test(fill_radius_underflow 5 "radius 'constant:1e-400': '1e-400' is out of the range of a double \\(underflows to 0\\)"
  fill ${SQ} --radius constant:1e-400)
frontpack_tool_test(fill_radius_overflow 5 "'1e400' is out of the range of a double \\(overflows to infinity\\)"
  fill ${SQ} --radius uniform:0.1,1e400)
frontpack_tool_test(fill_lognormal_default_bounds 5
  "the default lower bound MEDIAN / GSD\\^3 \\(MEDIAN '0\\.05', GSD '1e308'\\) underflows to 0; give the bounds"
  fill ${SQ} --radius lognormal:0.05,1e308)
frontpack_tool_test(check_nul_byte 7 "nul_byte\\.csv:2:5: y '0\\.5\\\\0' is not a number"
  check ${SQ} ${CMAKE_CURRENT_SOURCE_DIR}/data/tool/nul_byte.csv)

# --memory-limit (bytes, K/M/G/T suffixes): a request whose estimate exceeds it is refused up
# front; a run that would exceed it (a sliver whose overhanging disks the estimate misses) stops
# with the same exit code and a message naming the option.
frontpack_tool_test(fill_memory_limit_refused 5 "more than the limit of 1048576 bytes; use larger radii or raise memory_limit \\(--memory-limit\\)"
  fill ${SQ} --radius constant:1e-3 --memory-limit 1M)
frontpack_tool_test(fill_memory_limit_stops_the_run 5
  "the run would need more than the memory limit of 16777216 bytes: it had generated [0-9]+ disks.*raise memory_limit \\(--memory-limit\\)"
  fill --wkt "POLYGON((0 0,1 0,1 1e-5,0 0))" --method open --radius constant:4.5e-6 --memory-limit 16m)
frontpack_tool_test(fill_memory_limit_enough 0 "disks: +[0-9]+ \\(open form"
  fill --wkt "POLYGON((0 0,1 0,1 1e-5,0 0))" --method open --radius constant:4.5e-6 --memory-limit 64000000)
frontpack_tool_test(fill_memory_limit_bad 5 "--memory-limit '12Q': expected a number of bytes, with an optional suffix K, M, G or T"
  fill ${SQ} --memory-limit 12Q)
frontpack_tool_test(fill_memory_limit_too_large 5 "--memory-limit '99999999999999999999G': too large"
  fill ${SQ} --memory-limit 99999999999999999999G)

# Files and signals, as a user meets them (tests/tool/files_and_signals.py): /dev/stdout, devices,
# FIFOs and symlinks; a file given for two uses; SIGINT, SIGTERM and SIGHUP in every phase; fills
# that place no disk or stop at --max-disks. One test per class of cases.
find_program(FRONTPACK_TOOL_PYTHON3 python3)
if(FRONTPACK_TOOL_PYTHON3)
  foreach(group Outputs Clobbering Outcomes DeckDirectories Signals)
    add_test(NAME tool.files_and_signals.${group}
      COMMAND ${FRONTPACK_TOOL_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/tool/files_and_signals.py
              $<TARGET_FILE:frontpack_tool> ${PROJECT_SOURCE_DIR}/shapes -k ${group})
    set_tests_properties(tool.files_and_signals.${group} PROPERTIES TIMEOUT 900)
  endforeach()
  # The signal tests time the tool's exit: alone on the machine.
  set_tests_properties(tool.files_and_signals.Signals PROPERTIES RUN_SERIAL TRUE)
endif()

# The pictures' captions load fontconfig, whose patterns LeakSanitizer mistakes for leaks
# (lsan_fontconfig.supp says why): suppressed for the tool tests, for fontconfig only.
if(FRONTPACK_SANITIZE)
  get_property(tool_tests DIRECTORY PROPERTY TESTS)
  list(FILTER tool_tests INCLUDE REGEX "^tool\\.")
  set_property(TEST ${tool_tests} APPEND PROPERTY ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/lsan_fontconfig.supp:print_suppressions=0")
endif()

# The library's front options on the command line: --no-voids (the paper's forms as published:
# no void fill in the JSON counters), --window, --start (the closed form's first disk is centred
# there) and --clearance (the second disk, tangent to it, is that much farther); and their errors.
set(O ${TOOL_OUT}/fill_no_voids)
frontpack_tool_check(fill_no_voids 0 "closed form" FILES ${O}/s.json
  JSON ${O}/s.json "generation/void_fills=^0$" "certificate/dropped=^0$"
  ARGS fill ${SQ} --method closed --radius uniform:0.02,0.04 --no-voids --window 0 --json ${O}/s.json)
frontpack_tool_test(fill_no_voids_boundary 5 "boundary method keeps its voids" fill ${SQ} --no-voids)
set(O ${TOOL_OUT}/fill_start)
frontpack_tool_check(fill_start 0 "closed form" FILES ${O}/p.csv FILE_MATCHES ${O}/p.csv "^x,y,r\n0\\.25,0\\.75,0\\.01\n0\\.270000000001,0\\.75,"
  ARGS fill ${SQ} --method closed --radius constant:0.01 --start 0.25,0.75 --clearance 1e-12 -o ${O}/p.csv)
frontpack_tool_test(fill_start_not_closed 5 "start \\(--start\\) is where the closed form .* the boundary form has no start point"
  fill ${SQ} --start 0.5,0.5)
frontpack_tool_test(fill_start_bad 5 "--start '0.5': expected two numbers X,Y" fill ${SQ} --method closed --start 0.5)
frontpack_tool_test(fill_start_bad_number 5 "--start '0.5,abc': 'abc' is not a finite number; expected two numbers X,Y"
  fill ${SQ} --method closed --start 0.5,abc)
frontpack_tool_test(fill_start_many_polygons 5 "start \\(--start\\): the domain has 4 polygons"
  fill ${S}/islands.wkt --method closed --start 0.5,0.5)
frontpack_tool_test(fill_clearance_bad 5 "--clearance '-1': expected a gap > 0" fill ${SQ} --clearance -1)
frontpack_tool_test(fill_clearance_tiny 5 "clearance must be 0 \\(automatic\\) or a finite number >= [0-9.e-]+ for this domain and radius range, got 1e-300"
  fill ${SQ} --clearance 1e-300)
frontpack_tool_test(fill_window_bad 5 "--window '-2': expected a whole number" fill ${SQ} --window -2)
# --progress in a log: every phase named, the generation at 100%.
frontpack_tool_test(fill_progress_log 0 "progress: generating +100% of area.*progress: certifying [0-9]+ disks.*progress: measuring.*progress: writing .*fill_progress_log\\.csv.*disks: "
  fill ${SQ} --radius uniform:0.01,0.02 --progress -o ${TOOL_OUT}/fill_progress_log.csv)
# Types and simulator decks (fill --types, --deck): the options' errors, refused before any work.
set(deck_dir ${CMAKE_CURRENT_BINARY_DIR}/tool_deck)
frontpack_tool_test(fill_types_bad_edges 5 "type rule size: edges must increase strictly"
  fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --types size:0.05,0.03 -o ${CMAKE_CURRENT_BINARY_DIR}/t.csv)
frontpack_tool_test(fill_types_unknown 5 "expected size:E1,E2,... .* or region:A.wkt"
  fill ${S}/l_shape.wkt --types colour:red)
frontpack_tool_test(fill_types_missing_region 2 "cannot open '/nonexistent/r.wkt'"
  fill ${S}/l_shape.wkt --types region:/nonexistent/r.wkt)
frontpack_tool_test(fill_deck_unknown 5 "unknown simulator 'gromacs'; expected lammps, liggghts or yade"
  fill ${S}/l_shape.wkt --deck gromacs ${deck_dir} --density 2500)
frontpack_tool_test(fill_deck_needs_density 5 "--deck needs --density"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir})
frontpack_tool_test(fill_density_needs_deck 5 "--density sets up a simulator deck: it needs --deck"
  fill ${S}/l_shape.wkt --density 2500)
frontpack_tool_test(fill_density_per_type 5 "no density for type 2"
  fill ${S}/l_shape.wkt --types size:0.05 --deck lammps ${deck_dir} --density 1:2500)
frontpack_tool_test(fill_density_bad_type 5 "expected TYPE:DENSITY with TYPE from 1 to 1"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir} --density 2:2500)
frontpack_tool_test(fill_bad_thickness 5 "--thickness '-1': expected a finite number > 0"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir} --density 2500 --thickness -1)
frontpack_tool_test(fill_wall_radius_lammps_only 5 "--wall-radius sets the LAMMPS deck's wall disks"
  fill ${S}/l_shape.wkt --deck yade ${deck_dir} --density 2500 --wall-radius 0.01)
frontpack_tool_test(fill_deck_is_a_file 2 "is not a directory"
  fill ${S}/l_shape.wkt --deck lammps ${S}/l_shape.wkt --density 2500)
frontpack_tool_test(fill_deck_walls_too_large 5 "walls: .*use a smaller wall radius"
  fill --wkt "POLYGON((0 0,1 0,1 1,0 1,0 0),(0.5 0.5,0.5 0.51,0.51 0.51,0.51 0.5,0.5 0.5))" --radius uniform:0.02,0.04
  --deck lammps ${deck_dir} --density 2500 --wall-radius 0.1)
# Curve segments: every curve's count is known before any is split, summed and held to --max-disks
# and --memory-limit up front (40 circles at --max-deviation 1e-11 reached 6.1 GB); info and fill
# alike.
set(PIPES ${CMAKE_CURRENT_SOURCE_DIR}/data/cad/many_pipes.dxf)
frontpack_tool_test(info_curve_segments_memory 5
  "about 37[0-9][0-9][0-9][0-9][0-9] curve segments, needing about [0-9]+ bytes of memory, more than the limit of 104857600 bytes. use a larger max_deviation \\(--max-deviation\\) or raise memory_limit"
  info ${PIPES} --max-deviation 1e-9 --memory-limit 100M)
frontpack_tool_test(fill_curve_segments_max_disks 5
  "about 37[0-9][0-9][0-9][0-9][0-9] curve segments, more than max_disks = 1000000. use a larger max_deviation"
  fill ${PIPES} --max-deviation 1e-9 --max-disks 1000000)
frontpack_tool_test(info_curve_segments_within 0 "radius 1\\.7492, 360 deg -> 6570 tangent segments"
  info ${PIPES} --max-deviation 2e-7 --memory-limit 100M)

# Wall disks: a radius below the coordinates' precision is refused with the smallest that works (it
# gave 3 wall disks at one corner under a deck that said the rings were closed); the wall-disk count
# is estimated before any is placed and held to --max-disks and --memory-limit (1e-10 ended in
# bad_alloc, 1e-6 wrote 16 million wall disks). Nothing of the deck is written.
foreach(w 1e-30 1e-300)
  frontpack_tool_check(fill_deck_wall_radius_floor_${w} 5
    "walls: wall radius ${w} is below the precision floor of coordinates up to 2: .*use a wall radius of at least 3\\.6e-09"
    NO_FILES ${TOOL_OUT}/fill_deck_wall_radius_floor_${w}/d/deck.data
    ARGS fill ${S}/l_shape.wkt --deck lammps ${TOOL_OUT}/fill_deck_wall_radius_floor_${w}/d --density 2500
         --wall-radius ${w} --max-disks 0)
endforeach()
frontpack_tool_test(fill_deck_wall_count_default 5
  "about 1600[0-9]+ wall disks, more than max_disks = 50000000. use a wall radius of at least 3\\.3e-07 or raise"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir} --density 2500 --wall-radius 1e-8)
frontpack_tool_test(fill_deck_wall_count_max_disks 5
  "about 1600[0-9]+ wall disks, more than max_disks = 100000. use a wall radius of at least 0\\.00017 or raise"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir} --density 2500 --wall-radius 1e-5 --max-disks 100000)
frontpack_tool_test(fill_deck_wall_count_memory 5
  "about 1600[0-9]+ wall disks, needing about [0-9]+ bytes of memory, more than the limit of 104857600 bytes"
  fill ${S}/l_shape.wkt --deck lammps ${deck_dir} --density 2500 --wall-radius 1e-5 --memory-limit 100M)
set(O ${TOOL_OUT}/fill_deck_lammps)
frontpack_tool_check(fill_deck_lammps 0 "types: +2 \\(size:0.05\\): [1-9][0-9]* of type 1, [1-9][0-9]* of type 2.*wrote: +.*in.frontpack \\(lammps deck\\)"
  FILES ${O}/deck/deck.data ${O}/deck/in.frontpack ${O}/deck/domain.wkt ${O}/p.csv FILE_MATCHES ${O}/p.csv "^x,y,r,type\n"
  JSON ${O}/s.json "types/rule=^size:0.05$" "types/disks_per_type/1=^[1-9]" "deck/simulator=^lammps$"
       "deck/files/2=domain\\.wkt$"
  ARGS fill ${S}/l_shape.wkt --radius uniform:0.02,0.08 --types size:0.05 -o ${O}/p.csv --deck lammps ${O}/deck
       --density 1:2500,2:7800 --json ${O}/s.json)

# Fills with a target (docs/fraction.md): a fraction within 0.002, too high a fraction naming the
# one reached, a count, a level.
frontpack_tool_test(fill_fraction 0 "target: +fraction 0\\.7000 asked, 0\\.(69[89][0-9]|70[01][0-9]) reached \\(dense 0\\.[0-9]+; radii filled 1\\.[0-9]+x"
  fill ${S}/plate_with_holes.wkt --radius uniform:0.004,0.04 --fraction 0.7)
frontpack_tool_test(fill_fraction_too_high 5 "fraction 0\\.95: the boundary method reaches 0\\.8[0-9]+ for uniform: radius in \\[0\\.004, 0\\.04\\] in this domain"
  fill ${S}/plate_with_holes.wkt --radius uniform:0.004,0.04 --fraction 0.95)
frontpack_tool_test(fill_fraction_range 5 "--fraction .1\\.5.: expected a packing fraction \\(disk area / domain area\\) strictly between 0 and 1"
  fill ${S}/plate_with_holes.wkt --fraction 1.5)
frontpack_tool_test(fill_count_open 0 "disks: +500 \\(open form.*target: +count 500 asked"
  fill ${S}/plate_with_holes.wkt --method open --radius uniform:0.01,0.02 --count 500)
frontpack_tool_test(fill_count_boundary 5 "count: the boundary method starts its fronts on every wall at once.*use --method open"
  fill ${S}/plate_with_holes.wkt --count 500)
frontpack_tool_test(fill_height 0 "target: +fraction 0\\.[0-9]+ of the area filled, below y = 0\\.75 \\(area "
  fill ${S}/plate_with_holes.wkt --radius uniform:0.01,0.02 --height 0.75)
frontpack_tool_test(fill_height_below 5 "height -1: the level must lie above the domain's lowest point, y = 0"
  fill ${S}/plate_with_holes.wkt --height -1)

# Periodic cells (--periodic): overlaps across the seams are found and named, touching across a
# seam certifies, a shear cell's walls are walls, and bad cells are refused naming the option.
set(P ${CMAKE_CURRENT_SOURCE_DIR}/data/periodic)
frontpack_tool_test(check_periodic_seam_overlap 6
  "overlaps: +1 pair .*worst: disks 1 and 3 overlap by about 0\\.25.*overlap 1 3.*NOT certified"
  check --periodic 10,10 ${P}/seam_overlap.csv --all)
frontpack_tool_test(check_periodic_touching 0 "outside: +0 disks.*overlaps: +0 pairs.*certified"
  check --periodic 0,0,10,10 ${P}/touching.csv)
frontpack_tool_test(check_periodic_shear_walls 6 "outside: +2 disks .*worst: disk 4 .*overlaps: +0 pairs.*outside 5:"
  check --periodic 10,10 --periodic-axes x ${P}/touching.csv --all)
frontpack_tool_test(check_periodic_bad_number 5 "--periodic '10,abc': 'abc' is not a finite number"
  check --periodic 10,abc ${P}/touching.csv)
frontpack_tool_test(check_periodic_count 5 "--periodic '1,2,3': 3 numbers; expected LX,LY or XMIN,YMIN,XMAX,YMAX"
  check --periodic 1,2,3 ${P}/touching.csv)
frontpack_tool_test(check_periodic_empty 5 "--periodic '10,0': invalid domain: periodic cell .*empty"
  check --periodic 10,0 ${P}/touching.csv)
frontpack_tool_test(check_periodic_axes 5 "--periodic-axes 'z': expected xy or x"
  check --periodic 10,10 --periodic-axes z ${P}/touching.csv)
frontpack_tool_test(check_periodic_two_files 1 "with --periodic, give only DISKS"
  check --periodic 10,10 ${S}/unit_square.wkt ${P}/touching.csv)
frontpack_tool_test(check_periodic_and_wkt 1 "--wkt excludes --periodic"
  check --periodic 10,10 --wkt "POLYGON((0 0,1 0,1 1,0 0))" ${P}/touching.csv)
set(O ${TOOL_OUT}/render_periodic_images)
frontpack_tool_check(render_periodic_images 0 "wrote: .*p\\.png \\(png, 500 x 505, 168 disks\\)" PNG ${O}/p.png 500 505
  ARGS render --periodic 12,12.12435565298214 ${P}/hex_torus.csv --images --no-histogram --width 500 -o ${O}/p.png)
frontpack_tool_test(render_images_needs_periodic 1 "--images requires --periodic"
  render ${S}/unit_square.wkt ${P}/hex_torus.csv --images -o images.png)

# fill --periodic: the boundary method by default (as elsewhere) or the closed form, certified across
# the images (the certifier is the periodic one: a disk crossing a side would be culled by a walled
# check; the boundary method culls nothing, the closed form its disks beyond a shear cell's walls);
# the open form refused.
frontpack_tool_test(fill_periodic 0 "boundary form.*certified: ([0-9]+) generated, 0 culled .*, 0 dropped"
  fill --periodic 2,2 --radius discrete:0.02:0.5,0.028:0.5 --seed 5)
frontpack_tool_test(fill_periodic_closed 0 "closed form.*certified: ([0-9]+) generated, 0 culled .*, 0 dropped"
  fill --periodic 2,2 --radius discrete:0.02:0.5,0.028:0.5 --seed 5 --method closed)
frontpack_tool_test(fill_periodic_shear 0 "boundary form.*certified: [0-9]+ generated, 0 culled .*, 0 dropped"
  fill --periodic -1,0,1,0.5 --periodic-axes x --radius uniform:0.01,0.04)
frontpack_tool_test(fill_periodic_shear_closed 0 "closed form.*certified: [0-9]+ generated, [1-9][0-9]* culled .*, 0 dropped"
  fill --periodic -1,0,1,0.5 --periodic-axes x --radius uniform:0.01,0.04 --method closed)
frontpack_tool_test(fill_periodic_open 5
  "a periodic cell is filled by the boundary method or the closed form; the open form does not wrap around a cell"
  fill --periodic 2,2 --method open)
frontpack_tool_test(fill_periodic_narrow 5 "a periodic cell must be at least 10 rmax = 0.5 across each periodic direction"
  fill --periodic 0.4,2 --radius uniform:0.01,0.05)
frontpack_tool_test(fill_periodic_and_domain 1 "excludes"
  fill ${S}/unit_square.wkt --periodic 2,2)

# fill --jam: the jam stage's line in the summary and its JSON, certified; refused with a target
# fraction, with the library's message.
frontpack_tool_check(fill_jam 0
  "certified: [0-9]+ generated, 0 culled .*, 0 dropped.*jam: +[1-9][0-9]* disks inserted in [0-9]+ rounds, [0-9]+ relaxation steps"
  FILES ${TOOL_OUT}/fill_jam/j.csv ${TOOL_OUT}/fill_jam/j.json
  JSON ${TOOL_OUT}/fill_jam/j.json "jam/inserted=^[1-9][0-9]*$" "jam/rounds=^[1-9][0-9]*$" "seconds/jam=^[0-9]"
       "certificate/dropped=^0$"
  ARGS fill --wkt "POLYGON((0 0,1 0,1 1,0 1,0 0))" --radius discrete:0.014:0.5,0.0196:0.5 --seed 1 --jam
       -o ${TOOL_OUT}/fill_jam/j.csv --json ${TOOL_OUT}/fill_jam/j.json)
frontpack_tool_test(fill_jam_fraction 5 "jam makes the packing as dense as it gets; a target fraction leaves gaps"
  fill ${S}/unit_square.wkt --jam --fraction 0.6)

# Every input read is bounded (docs/robustness.md, "Input sizes"): /dev/zero as a domain, a region,
# a size table and a disk file is refused at the bound, exit 2, naming the file.
set(_zero_regex "cannot read '/dev/zero': it is longer than 1 [GM]iB")
frontpack_tool_test(info_dev_zero 2 "${_zero_regex}" info /dev/zero)
frontpack_tool_test(fill_region_dev_zero 2 "${_zero_regex}" fill ${S}/unit_square.wkt --types region:/dev/zero)
frontpack_tool_test(check_dev_zero 2 "${_zero_regex}" check ${S}/unit_square.wkt /dev/zero --disks-format csv)

# --count: one message for every value out of range; a count run is estimated by its count; a
# count the domain cannot hold is said, not passed over.
frontpack_tool_test(fill_count_zero 5 "--count '0': expected a whole number from 1 to 18446744073709551615 *$"
  fill ${S}/unit_square.wkt --method open --count 0)
frontpack_tool_test(fill_count_negative 5 "--count '-1': expected a whole number from 1 to 18446744073709551615 \\(digits only\\)"
  fill ${S}/unit_square.wkt --method open --count -1)
frontpack_tool_test(fill_count_one_max_disks_one 0 "disks: +1 \\(open form.*target: +count 1 asked"
  fill ${S}/unit_square.wkt --method open --count 1 --max-disks 1)
frontpack_tool_test(fill_count_closed_max_disks 0 "disks: +10 \\(closed form.*target: +count 10 asked"
  fill ${S}/unit_square.wkt --method closed --count 10 --max-disks 10)
frontpack_tool_check(fill_count_short 0 "target: +count 5000 asked, 237 placed: the domain holds no more"
  JSON ${TOOL_OUT}/fill_count_short/c.json "target/count_requested=^5000$" "target/count_achieved=^237$"
  ARGS fill ${S}/unit_square.wkt --method open --count 5000 --json ${TOOL_OUT}/fill_count_short/c.json)

# Exit 8 names why no disk was placed (src/fill/limits.cpp, NothingFitsError): the radii, a fraction that
# keeps none, a start point outside the domain, the clearance, the precision at the coordinates.
frontpack_tool_check(fill_nothing_fits_radii 8 "no disk fits: the smallest radius, 2 \\(constant: radius 2\\), is larger than any disk this domain holds \\(none of radius above 0\\.5\\); use smaller radii; nothing written"
  NO_FILES ${TOOL_OUT}/fill_nothing_fits_radii/p.csv
  ARGS fill ${S}/unit_square.wkt --radius constant:2 -o ${TOOL_OUT}/fill_nothing_fits_radii/p.csv)
frontpack_tool_test(fill_nothing_fits_fraction 8 "fraction 1e-07 of the area 1 is 1e-07, less than one disk of the smallest radius, 0\\.01 \\(area 0\\.000314"
  fill ${S}/unit_square.wkt --fraction 1e-7)
frontpack_tool_test(fill_nothing_fits_start 8 "the start point \\(5 5\\) lies outside the domain's bounding box \\[0, 1\\] x \\[0, 1\\].*give a start point in the domain"
  fill ${S}/unit_square.wkt --method closed --start 5,5)
frontpack_tool_test(fill_nothing_fits_clearance 8 "the clearance 1 \\(clearance, --clearance\\).*leaves no room.*use a smaller clearance"
  fill ${S}/unit_square.wkt --clearance 1)
frontpack_tool_test(fill_nothing_fits_precision 8 "at the scale of this fill \\(largest \\|coordinate\\| \\+ 5 rmax = 1e\\+15\\) doubles are 0\\.125 apart.*move the domain near the origin"
  fill --wkt "POLYGON((1e15 1e15,1.00000000000001e15 1e15,1.00000000000001e15 1.00000000000001e15,1e15 1.00000000000001e15,1e15 1e15))")
# A periodic cell far from the origin against its size is refused up front: the clearance there
# exceeds rmax, and a cell under 10 clearances across lets a tangent disk's nearest image be
# another (a cell a few ulps wide at 1.4e10 had overlapping disks placed; fuzz regression
# periodic-cell-few-ulps-wide-at-1.4e10-overlap).
frontpack_tool_test(fill_periodic_precision 5 "a periodic cell must be at least 10 times the clearance .*\\(largest \\|coordinate\\| 1000000000000010: clearance 14\\.2[0-9]+, larger than rmax\\), 142\\.1[0-9]+, across each periodic direction; it is 10 x 10: move the cell near the origin"
  fill --periodic 1e15,1e15,1.00000000000001e15,1.00000000000001e15)

# The one number rule for the tool's options: an empty value is refused like any other bad one
# (--clearance "" was taken as not given). run_tool.cmake's argument list cannot carry an empty
# argument, so these run the tool directly and match its message.
foreach(_case IN ITEMS "fill_clearance_empty;--clearance;fill;${SQ}" "fill_fraction_empty;--fraction;fill;${SQ}"
                       "stats_samples_empty;--samples;stats;${SQ};${TD}/good.csv")
  list(POP_FRONT _case _name _option)
  add_test(NAME tool.${_name} COMMAND $<TARGET_FILE:frontpack_tool> ${_case} ${_option} "")
  set_tests_properties(tool.${_name} PROPERTIES PASS_REGULAR_EXPRESSION
                       "^frontpack: ${_option} '': expected a value, got an empty one\n$")
endforeach()
