# Warning and sanitizer flags shared by every cartan target.
# cartan_set_warnings(<target> [NOT_INSTRUMENTED]): with CARTAN_SANITIZE, the target's own code is
# compiled with AddressSanitizer + UndefinedBehaviorSanitizer unless NOT_INSTRUMENTED, and it is
# always linked with their runtime (the library it links is instrumented).
function(cartan_set_warnings target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "NOT_INSTRUMENTED" "" "")
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                         -Wno-sign-conversion $<$<BOOL:${CARTAN_WERROR}>:-Werror>)
  if(CARTAN_SANITIZE)
    if(NOT ARG_NOT_INSTRUMENTED)
      target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                             -fno-sanitize-recover=all)
    endif()
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# libFuzzer's coverage feedback (CARTAN_FUZZ) for the code the fuzz targets run: the library and
# the CLI core. The tests in the same sanitizer build are not instrumented for it (the sanitizer
# runtime provides the coverage hooks when they link the library).
function(cartan_fuzz_coverage target)
  if(CARTAN_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
