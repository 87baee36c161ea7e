# Warning and sanitizer flags shared by every cartan target.
function(cartan_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                         -Wno-sign-conversion $<$<BOOL:${CARTAN_WERROR}>:-Werror>)
  if(CARTAN_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                           -fno-sanitize-recover=all)
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
