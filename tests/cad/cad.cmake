# Tests of the tool on CAD and GIS domains (tests/data/cad/, made by make_fixtures.py there).
# Included from tests/CMakeLists.txt after tool_tests.cmake and readers/readers.cmake.
set(C ${CMAKE_CURRENT_SOURCE_DIR}/data/cad)
if(FRONTPACK_WITH_DXFLIB)
  frontpack_tool_test(cad_info_drum 0 "holes: +1.*ignored: +1 annotation.*curves: +2 arcs -> [0-9]+ segments.*CIRCLE \\(handle 2F, line 2026\\): radius 1, 360 deg -> 71 chords.*tangent segments"
    info ${C}/drum.dxf)
  frontpack_tool_test(cad_info_deviation 0 "CIRCLE \\(handle 2F, line 2026\\): radius 1, 360 deg -> 23 chords"
    info ${C}/drum.dxf --max-deviation 0.01)
  frontpack_tool_test(cad_info_format 0 "curves: +2 arcs" info ${C}/drum.dxf --domain-format dxf)
  frontpack_tool_test(cad_fill_curves 0 "certified: .*0 dropped.*curves: +2 arcs -> .*deviation <= 0.0009"
    fill ${C}/drum.dxf --radius uniform:0.01,0.03 --seed 2)
  frontpack_tool_test(cad_open_polyline 3 "open_polyline.dxf: LWPOLYLINE \\(handle 2F, line 2026\\): open contour: its end \\(1 1\\)"
    info ${C}/open_polyline.dxf)
  frontpack_tool_test(cad_ellipse 3 "ELLIPSE \\(handle 30, line 2046\\): frontpack reads CIRCLE, ARC, LINE" info ${C}/ellipse.dxf)
  frontpack_tool_test(cad_crossing 4 "invalid domain: '.*crossing.dxf', CIRCLE \\(handle (2F|30), line 20.6\\) and CIRCLE \\(handle (2F|30), line 20.6\\): .* cross"
    info ${C}/crossing.dxf)
  frontpack_tool_test(cad_empty 3 "empty.dxf: no closed contour" info ${C}/empty.dxf)
  frontpack_tool_test(cad_zero_radius 3 "zero_radius.dxf: CIRCLE \\(handle 2F, line 2026\\): radius 0; expected a finite number > 0"
    info ${C}/zero_radius.dxf)
  frontpack_tool_test(cad_branching 3 "branching.dxf: LINE .*: the end \\(1 0\\) meets 2 other ends" info ${C}/branching.dxf)
  frontpack_tool_test(cad_bad_deviation 5 "--max-deviation '-1': expected a finite number >= 0" info ${C}/drum.dxf --max-deviation -1)
  frontpack_tool_test(cad_tiny_deviation 5 "curve deviation 1e-15 is too small for CIRCLE" info ${C}/drum.dxf --max-deviation 1e-15)
  set(O ${TOOL_OUT}/cad_fill_json)
  # (No square bracket in the pattern: CMake's lists do not split inside one.)
  frontpack_tool_check(cad_fill_json 0 "^$" FILE_MATCHES ${O}/drum.json
    "\"curves\": .*\"entity\": \"CIRCLE \\(handle 2F, line 2026\\)\".*\"domain_inside\": true.*\"segments\": 71"
    ARGS fill ${C}/drum.dxf --radius uniform:0.01,0.03 --seed 2 -q --json ${O}/drum.json)
  # Every disk of a fill inside the TRUE circles, checked exactly against the DXF's circles.
  if(frontpack_reader_python)
    add_test(NAME tool.cad_fill_in_true_circles
      COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_SOURCE_DIR}/cad/fill_in_true_circles.py
              $<TARGET_FILE:frontpack_tool> ${C}/drum.dxf ${CMAKE_CURRENT_BINARY_DIR}/cad_fill
              --radius uniform:0.01,0.03 --seed 5)
    add_test(NAME tool.cad_fill_in_true_circles_pipes
      COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_SOURCE_DIR}/cad/fill_in_true_circles.py
              $<TARGET_FILE:frontpack_tool> ${C}/many_pipes.dxf ${CMAKE_CURRENT_BINARY_DIR}/cad_fill_pipes
              --radius uniform:0.2,0.5 --seed 5 --method closed)
    # The check itself: a polygon made the unsafe way lets disks out of the true circles.
    add_test(NAME tool.cad_fill_in_true_circles_catches_unsafe
      COMMAND ${frontpack_reader_python} ${CMAKE_CURRENT_SOURCE_DIR}/cad/fill_in_true_circles.py
              $<TARGET_FILE:frontpack_tool> ${C}/drum.dxf ${CMAKE_CURRENT_BINARY_DIR}/cad_fill_naive --naive
              --radius uniform:0.01,0.03 --seed 5)
    set_tests_properties(tool.cad_fill_in_true_circles_catches_unsafe PROPERTIES WILL_FAIL TRUE TIMEOUT 300)
    set_tests_properties(tool.cad_fill_in_true_circles tool.cad_fill_in_true_circles_pipes
                         PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
  endif()
  # What a DXF file must be (docs/cad-gis.md): cut short, bad numbers, broken structure and
  # extreme bulges are refused (exit 3) naming the line and the text; $INSUNITS is said.
  set(R ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/regressions/dxf)
  frontpack_tool_test(cad_truncated 3 "drum-cut-after-the-bore-radius-lost-the-bore: the file ends before EOF, at line 54 \\(inside section 'ENTITIES'\\)"
    info ${R}/drum-cut-after-the-bore-radius-lost-the-bore --domain-format dxf)
  frontpack_tool_test(cad_bulge_nan 3 "LWPOLYLINE \\(handle 2F, line 6\\): group 42 \\(line 20\\): 'nan' is not a finite number"
    info ${R}/bulge-nan-read-as-a-straight-edge --domain-format dxf)
  frontpack_tool_test(cad_bulge_hex 3 "group 42 \\(line 20\\): '0x10' is not a number"
    info ${R}/bulge-0x10-read-as-0 --domain-format dxf)
  frontpack_tool_test(cad_centre_nan 3 "CIRCLE \\(handle 30, line 34\\): group 10 \\(line 40\\): 'nan' is not a finite number"
    fill ${R}/circle-centre-nan-moved-to-x-0 --domain-format dxf --radius constant:0.1)
  frontpack_tool_test(cad_empty_radius 3 "group 40 \\(line 44\\): expected a number, got nothing"
    info ${R}/empty-radius-read-as-an-uninitialised-double --domain-format dxf)
  frontpack_tool_test(cad_tiny_bulge 3 "vertex 0: bulge '-1e-300' \\(line 20\\) is outside 1e-12 <= \\|bulge\\| <= 1e12"
    info ${R}/bulge-minus-1e-300-named-a-subnormal-vertex --domain-format dxf)
  frontpack_tool_test(cad_huge_bulge 3 "vertex 0: bulge '1e308' \\(line 20\\)"
    info ${R}/bulge-1e308-said-radius-nan --domain-format dxf)
  frontpack_tool_test(cad_lost_value 3 "line 10: group 0 '90' is not a name .*a value line may be missing"
    info ${R}/lost-value-line-named-a-group-code-as-entity --domain-format dxf)
  frontpack_tool_test(cad_units 0 "units: +meters \\(\\$INSUNITS\\)" info ${C}/drum.dxf)
  set(O ${TOOL_OUT}/cad_fill_json_units)
  frontpack_tool_check(cad_fill_json_units 0 "units: +meters" FILE_MATCHES ${O}/drum.json "\"units\": \"meters\""
    ARGS fill ${C}/drum.dxf --radius uniform:0.01,0.03 --seed 2 --json ${O}/drum.json)
else()
  frontpack_tool_test(cad_no_dxf_reader 5 "built without dxflib" info ${C}/drum.dxf)
endif()
if(FRONTPACK_WITH_GDAL)
  # GDAL is a module loaded on the first GeoJSON or Shapefile (docs/cad-gis.md), never linked.
  add_test(NAME tool.gdal_not_linked COMMAND ldd $<TARGET_FILE:frontpack_tool>)
  set_tests_properties(tool.gdal_not_linked PROPERTIES FAIL_REGULAR_EXPRESSION "libgdal|libopenblas"
                       PASS_REGULAR_EXPRESSION "libc\\.so")
  frontpack_tool_test(cad_info_geojson 0 "polygons: +1.*holes: +1.*area: +3" info ${C}/plate.geojson)
  frontpack_tool_test(cad_info_shapefile 0 "polygons: +2.*holes: +1.*area: +4.75" info ${C}/islands.shp)
  frontpack_tool_test(cad_geojson_point 3 "points.geojson: layer points, feature 0: geometry type Point" info ${C}/points.geojson)
  # A GeoJSON number out of range is refused by the one number rule, not read as 0 by GDAL.
  frontpack_tool_test(cad_geojson_underflow 3 "underflow.geojson: line 3: '1e-400' is out of the range of a double \\(underflows to 0\\)"
    info ${C}/underflow.geojson)
else()
  frontpack_tool_test(cad_no_gis_reader 5 "built without GDAL" info ${C}/plate.geojson)
endif()
frontpack_tool_test(cad_other_extension_is_wkt 3 "WKT error in '.*make_fixtures.py' at line 1" info ${C}/make_fixtures.py)
frontpack_tool_test(cad_bad_format 5 "domain format 'svg': expected auto, wkt, dxf" info ${C}/drum.dxf --domain-format svg)
