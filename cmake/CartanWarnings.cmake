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
  # it cost a fifth of the instrumented compile (src/general/solve_sphere.cpp, clang 14 at -O1:
  # 41.7 s of CPU with it, 33.6 s without; bench/README.md "Build time").
  if(CARTAN_SANITIZE)
    if(NOT ARG_NOT_INSTRUMENTED)
      target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize=object-size
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
function(cartan_fuzz_coverage target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "SOURCES")
  if(NOT CARTAN_FUZZ)
    return()
  endif()
  if(ARG_SOURCES)
    set_source_files_properties(${ARG_SOURCES} TARGET_DIRECTORY ${target} PROPERTIES
                                COMPILE_OPTIONS -fsanitize=fuzzer-no-link)
  else()
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
