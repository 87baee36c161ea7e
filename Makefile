# The two commands a newcomer needs (README):
#   make run   - install missing Debian packages, build, reproduce the paper's experiments
#   make test  - install missing Debian packages, build, run every test (also under ASan+UBSan), fuzz
BUILD ?= build
BUILD_ASAN ?= build-asan
FUZZ_SECONDS ?= 15
FUZZ_RUNS ?= 1000000
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps deps-docs docs build build-asan build-trees compile-release compile-asan build-fuzz fuzz test test-release test-asan test-fuzz test-install run bench clean

all: build

deps:
	bash scripts/install-deps.sh

# Sphinx, Doxygen, Chromium and WebDriver: for `make docs` and the site's browser test in `make test`.
deps-docs:
	bash scripts/install-deps.sh docs

# The release tree builds what ships (library, CLI, Python module, examples); the C++ tests are
# compiled once, in the sanitizer tree (CARTAN_CXX_TESTS; README.md "What runs where"). For them
# here too: make build CMAKE_FLAGS=-DCARTAN_CXX_TESTS=ON.
CONFIGURE_RELEASE = cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DCARTAN_CXX_TESTS=OFF $(CMAKE_FLAGS)

build: deps
	$(CONFIGURE_RELEASE)
	cmake --build $(BUILD) -j $(JOBS)

# The sanitizer build: clang, AddressSanitizer + UndefinedBehaviorSanitizer on every target, and
# the libFuzzer targets of tests/fuzz (CARTAN_FUZZ) in the same tree, so that the library is
# compiled once for the tests and the fuzzers. -O1 -g0: reports name the functions of the stack;
# line tables (-g1) cost 14 % more compile time (measured on tests/kernels/manifold/test_general.cpp, 49 s
# against 42 s of CPU): for file and line, rebuild with SANITIZE_FLAGS="-O1 -g1 -DNDEBUG". Measured side by side (bench/README.md, "Build time"): clang compiles the heaviest
# translation units about twice as fast as GCC with the same sanitizer flags, in half the memory.
SANITIZE_FLAGS ?= -O1 -g0 -DNDEBUG

CONFIGURE_ASAN = CC=clang CXX=clang++ cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(SANITIZE_FLAGS)" -DCARTAN_FUZZ=ON -DCARTAN_FUZZ_SECONDS=$(FUZZ_SECONDS) \
	  -DCARTAN_BUILD_BENCH=OFF -DCARTAN_BUILD_EXAMPLES=OFF -DCARTAN_CXX_TESTS=ON $(CMAKE_FLAGS)

build-asan: deps
	$(CONFIGURE_ASAN)
	cmake --build $(BUILD_ASAN) -j $(JOBS)

# Both trees by one make whose $(JOBS) job slots the two share (GNU make's jobserver, through the
# generated Makefiles): no more compilers at once than `make build` alone, so no more memory, and
# the slots one tree leaves idle (its links, the last units before a target that needs them all)
# compile the other's units. `make test` builds this way.
build-trees: deps
	$(CONFIGURE_RELEASE)
	$(CONFIGURE_ASAN)
	+$(MAKE) --no-print-directory -j $(JOBS) compile-release compile-asan

compile-release:
	+$(MAKE) --no-print-directory -C $(BUILD)
compile-asan:
	+$(MAKE) --no-print-directory -C $(BUILD_ASAN)

# Label `install` (the fresh-clone `pip install`, which compiles everything again): make test-install.
RUN_RELEASE_TESTS = ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE install
SANITIZER_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
RUN_SANITIZER_TESTS = $(SANITIZER_ENV) ctest --test-dir $(BUILD_ASAN) --output-on-failure -j $(JOBS)

test-release: build deps-docs
	$(RUN_RELEASE_TESTS)

test-asan: build-asan
	$(RUN_SANITIZER_TESTS) -LE fuzz

# libFuzzer targets (tests/fuzz/README.md), in the sanitizer build: each target over its corpus,
# then FUZZ_SECONDS of fuzzing each; fails on any finding.
build-fuzz: build-asan

test-fuzz: build-asan
	$(RUN_SANITIZER_TESTS) -L fuzz

# A long campaign: FUZZ_RUNS executions per target; new inputs in $(BUILD_ASAN)/tests/fuzz/corpus.
fuzz: build-asan
	for target in $$(ls $(BUILD_ASAN)/tests/fuzz | grep '^fuzz_'); do \
	  mkdir -p $(BUILD_ASAN)/tests/fuzz/corpus/$$target $(BUILD_ASAN)/tests/fuzz/artifacts/$$target && \
	  $(BUILD_ASAN)/tests/fuzz/$$target -runs=$(FUZZ_RUNS) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
	    -artifact_prefix=$(BUILD_ASAN)/tests/fuzz/artifacts/$$target/ \
	    $(BUILD_ASAN)/tests/fuzz/corpus/$$target tests/fuzz/corpus/$$target || exit 1; \
	done

# make test: both trees compiled together (build-trees), the release tests, then the sanitizer
# tests and the fuzzers in one ctest (the fuzzers first, the tests beside them).
test: build-trees deps-docs
	$(RUN_RELEASE_TESTS)
	$(RUN_SANITIZER_TESTS)

# `pip install --no-build-isolation` of a fresh clone of HEAD into a fresh virtual environment, then
# `import cartan` from elsewhere (tests/package/pip_install.py; compiles the module: ~15-20 CPU-minutes).
test-install: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DCARTAN_CXX_TESTS=OFF $(CMAKE_FLAGS)
	CMAKE_BUILD_PARALLEL_LEVEL=$(JOBS) ctest --test-dir $(BUILD) --output-on-failure -L install

run: build
	bash scripts/run-experiments.sh $(BUILD)

# Benchmarks (not part of the tests): Google Benchmark, then C++ vs Python side by side.
bench: build
	cmake --build $(BUILD) -j $(JOBS) --target cartan_benchmarks
	mkdir -p out
	$(BUILD)/bench/bench_transported --benchmark_min_time=0.2 | tee out/bench_transported.txt
	$(BUILD)/bench/bench_scheme | tee out/bench_scheme.txt
	$(BUILD)/bench/bench_library --benchmark_repetitions=5 --benchmark_report_aggregates_only=true | tee out/bench_library.txt
	/usr/bin/python3 bench/compare_with_python.py --module $(BUILD)/python --repeat 3 --markdown out/bench_compare.md
	/usr/bin/python3 bench/compare_collocation.py --cartan $(BUILD)/cartan --bench $(BUILD)/bench/bench_collocation --markdown out/bench_collocation.md
	/usr/bin/python3 bench/compare_collocation_warm.py --timer $(BUILD)/bench/collocation_timer --markdown out/bench_collocation_warm.md
	/usr/bin/python3 bench/compare_solve_bvp.py --module $(BUILD)/python --rounds 5 --markdown out/bench_solve_bvp.md
	/usr/bin/python3 bench/sweep_scaling.py --cartan $(BUILD)/cartan --repeat 3 | tee out/sweep_scaling.md

# The documentation site (docs/site) into $(BUILD)/docs/html: the user guide and the other
# docs/*.md, the README, the Python reference (docstrings; needs the compiled module), the C++
# reference (Doxygen + Breathe), the gallery (figures and outputs made afresh by the scripts of
# `make run` into $(BUILD)/docs/gallery). Sphinx runs with warnings as errors. Builds only what the
# site needs: the Python module and the C++ examples. `make test` builds and checks it too
# (ctest -L docs: tests/site, every page in headless Chromium).
docs: deps deps-docs
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS) --target cartan_python geometry_tour custom_group custom_lagrangian
	bash scripts/build-docs.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) out
