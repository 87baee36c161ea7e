# Warning and sanitizer flags shared by every cartan target.
# cartan_set_warnings(<target> [NOT_INSTRUMENTED]): with CARTAN_SANITIZE, the target's own code is
# compiled with AddressSanitizer + UndefinedBehaviorSanitizer unless NOT_INSTRUMENTED, and it is
# always linked with their runtime (the library it links is instrumented).
function(cartan_set_warnings target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "NOT_INSTRUMENTED" "" "")
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                         -Wno-sign-conversion $<$<BOOL:${CARTAN_WERROR}>:-Werror>)
  # UBSan's object-size check is left to ASan, which checks every load and store against the
  # object's bounds at run time (object-size checks only those whose size the optimiser can see):
  # it cost a fifth of the instrumented compile (src/methods/solve_sphere.cpp, clang 14 at -O1:
  # 41.7 s of CPU with it, 33.6 s without; bench/README.md "Build time"). So are, outside the code
  # that handles input (CARTAN_UBSAN_INPUT_CHECKS, below), UBSan's null, alignment and
  # pointer-overflow checks: the accesses they anticipate (through a null or misaligned pointer,
  # or one that wrapped) are faults or out-of-bounds accesses that ASan reports with their stack
  # when they happen. Together they cost a third of the instrumented compile (solve_sphere.cpp:
  # 24.5 s of CPU with them, 15.7 s without, 14.9 s with ASan alone); every other UBSan check
  # (integer overflow, shifts, bounds, float casts, enums, bools, vptr, returns, ...) stays.
  if(CARTAN_SANITIZE)
    if(NOT ARG_NOT_INSTRUMENTED)
      target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                             -fno-sanitize=object-size,null,alignment,pointer-overflow
                             -fno-omit-frame-pointer -fno-sanitize-recover=all)
    endif()
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# libFuzzer's coverage feedback (CARTAN_FUZZ) for the code the fuzz targets run: the CLI core, or
# the given sources of a target (the library's units that parsing reaches; the fuzz targets run
# no solver, so the solvers' units are not instrumented for it: 10 % of their compile). The tests
# in the same sanitizer build are not instrumented for it (the sanitizer runtime provides the
# coverage hooks when they link the library).
#   cartan_fuzz_coverage(<target> [SOURCES <files...>])
#
# The code that handles input (the code the fuzz targets run, and the targets themselves) keeps
# every UBSan check but object-size: CARTAN_UBSAN_INPUT_CHECKS, after cartan_set_warnings' flags.
set(CARTAN_UBSAN_INPUT_CHECKS -fsanitize=null,alignment,pointer-overflow)
function(cartan_fuzz_coverage target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "SOURCES")
  if(NOT CARTAN_FUZZ)
    return()
  endif()
  if(ARG_SOURCES)
    set_source_files_properties(${ARG_SOURCES} TARGET_DIRECTORY ${target} PROPERTIES
                                COMPILE_OPTIONS "-fsanitize=fuzzer-no-link;${CARTAN_UBSAN_INPUT_CHECKS}")
  else()
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link ${CARTAN_UBSAN_INPUT_CHECKS})
  endif()
endfunction()
