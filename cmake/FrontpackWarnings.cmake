# Compile settings for frontpack's own targets (never applied globally).
#
# -ffp-contract=off: no fused multiply-add contraction, so that the floating-point
# constructions (and hence the output) are the same on every build of the same source.
# -fno-math-errno: square roots compile to the instruction alone, without the branch to the
# library call that would set errno for a negative argument (we never read errno after math;
# the results are the same).
function(frontpack_target_settings target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
                                   -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual
                                   -ffp-contract=off -fno-math-errno>
    $<$<AND:$<CXX_COMPILER_ID:GNU,Clang>,$<BOOL:${FRONTPACK_WERROR}>>:-Werror>)
  if(FRONTPACK_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=all
                                             -fno-omit-frame-pointer)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
  if(FRONTPACK_DRIVER_OPTIMIZE AND NOT target STREQUAL "frontpack")
    # Every target but the library: the tool, the tests, the fuzz drivers, the benchmarks.
    target_compile_options(${target} PRIVATE ${FRONTPACK_DRIVER_OPTIMIZE})
  endif()
  if(FRONTPACK_BUILD_FUZZERS)
    # Coverage feedback for libFuzzer in every target of ours; the fuzz programs add the driver.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
