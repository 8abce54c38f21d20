# partimix: the two set-up commands are `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 600
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: deps build demo test test-sanitize fuzz-build fuzz fuzz-smoke fuzz-regressions bench format \
  clean

deps:
	./scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	rm -rf out/demo
	./$(BUILD_DIR)/partimix run cases/bohl_planetary_cmc.yaml --set time.end=0.75 --out out/demo
	./$(BUILD_DIR)/partimix plot out/demo

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The sanitizer and fuzz builds compile at -O1 with line tables only: under ASan, GCC takes some
# three times as long at -O2 -g (58 s against 21 s for src/sph/sph_solver.cpp), and their
# clean builds are most of CI's time.
INSTRUMENTED_FLAGS ?= -O1 -g1 -DNDEBUG

# Unit tests built with AddressSanitizer and UndefinedBehaviorSanitizer (run by CI).
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARTIMIX_SANITIZE=ON \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" -DPARTIMIX_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) -L unit

# libFuzzer targets of fuzz/ (clang, ASan, UBSan; fuzz/README.md): each runs FUZZ_SECONDS, one
# after the other, corpus in $(FUZZ_DIR)/corpus/<target>, findings in $(FUZZ_DIR)/artifacts/.
# The checkpoint seeds include a fresh checkpoint when $(BUILD_DIR)/partimix is built.
fuzz-build: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" -DPARTIMIX_FUZZ=ON \
	  -DPARTIMIX_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target fuzz_targets
	./fuzz/make_seeds.sh $(FUZZ_DIR)/seeds $(wildcard $(BUILD_DIR)/partimix)

fuzz: fuzz-build
	./fuzz/run.sh $(FUZZ_DIR) $(FUZZ_SECONDS)

# 30 s per target, run by CI.
fuzz-smoke:
	$(MAKE) fuzz FUZZ_SECONDS=30

# Each saved finding of fuzz/regressions/<target>/ run once (fails while one still fails).
fuzz-regressions: fuzz-build
	./fuzz/run_regressions.sh $(FUZZ_DIR)

# One process per benchmark family: the peak resident set per particle is that of the process.
bench: build
	for family in dam_break_3d planetary_mixer_cmc drum_10k drum_ellipsoids_10k drum_100k ellipsoid_contact_warm mpm_2d_10k mpm_2d_100k mpm_3d_10k mpm_3d_100k checkpoint_write checkpoint_read; do \
	  ./$(BUILD_DIR)/bench/partimix_bench --benchmark_counters_tabular=true \
	    --benchmark_filter="^$$family(/|$$)" || exit 1; \
	done

format:
	find src tests bench fuzz -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR)
