# The two commands a newcomer needs (README):
#   make run   - install missing Debian packages, build, reproduce the paper's experiments
#   make test  - install missing Debian packages, build, run every test (also under ASan+UBSan)
BUILD ?= build
BUILD_ASAN ?= build-asan
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps build build-asan test test-release test-asan run bench clean

all: build

deps:
	bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)

build-asan: deps
	cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCARTAN_SANITIZE=ON -DCARTAN_BUILD_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(BUILD_ASAN) -j $(JOBS)

test-release: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

test-asan: build-asan
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(BUILD_ASAN) --output-on-failure -j $(JOBS) -LE slow

test: test-release test-asan

run: build
	bash scripts/run-experiments.sh $(BUILD)

# Benchmarks (not part of the tests): Google Benchmark, then C++ vs Python side by side.
bench: build
	mkdir -p out
	$(BUILD)/bench/bench_transported --benchmark_min_time=0.2 | tee out/bench_transported.txt
	/usr/bin/python3 bench/compare_with_python.py --cartan $(BUILD)/cartan --repeat 3 --markdown out/bench_compare.md
	/usr/bin/python3 bench/compare_collocation.py --cartan $(BUILD)/cartan --bench $(BUILD)/bench/bench_collocation --markdown out/bench_collocation.md
	/usr/bin/python3 bench/sweep_scaling.py --cartan $(BUILD)/cartan --repeat 3 | tee out/sweep_scaling.md

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) out
