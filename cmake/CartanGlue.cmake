# The glue (the Python bindings, the CLI): code that converts arguments and results and calls the
# library's compiled solves, whose own loops are not where a solve spends its time. Compiled at -O1
# outside the sanitizer tree: the bindings 286 s of GCC CPU at -O3 and 180 s at -O1, the CLI 35 s
# and 15 s (bench/README.md, "2026-12-07: the glue at -O1"); a solve's instructions are unchanged.
#
# The glue instantiates inline functions that the library's solves also call (a quadric's transport
# along a step, a group's exp). Each object carries its own copy; the linker keeps the first it
# meets and every caller in the binary calls that one. Linked as usual, the glue's objects come
# first and the solves would run its -O1 copies (a Python sphere solve took 1.15x the thread CPU).
# So the library's archive is loaded whole before the glue's objects (link options precede the
# objects on the link line): the library's -O3 copies are met first, and only code that the library
# does not instantiate keeps the glue's copy.
#   cartan_compile_as_glue(<target>)            -O1 for the target's own units
#   cartan_link_library_first(<target>)         the library's copies win in this binary
# A target that links glue compiled this way (an executable or a module) calls the second. Both
# only with GNU ld's --whole-archive (not on Apple's linker). The first never in the sanitizer
# tree; the second there too, for the test suites compiled at -O0 (tests/CMakeLists.txt), whose
# own copies would otherwise replace the library's instrumented -O1 ones.
function(cartan_compile_as_glue target)
  if(NOT CARTAN_SANITIZE AND NOT APPLE AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:-O1>)
  endif()
endfunction()

function(cartan_link_library_first target)
  if(NOT APPLE AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_link_options(${target} PRIVATE "LINKER:--whole-archive" "$<TARGET_FILE:cartan>"
                        "LINKER:--no-whole-archive")
  endif()
endfunction()
