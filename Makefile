# partimix: the two set-up commands are `make demo` and `make test` (see README.md).
BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: deps build demo test test-sanitize bench format clean

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

# Unit tests built with AddressSanitizer and UndefinedBehaviorSanitizer (run by CI).
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPARTIMIX_SANITIZE=ON \
	  -DPARTIMIX_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) -L unit

# One process per benchmark family: the peak resident set per particle is that of the process.
bench: build
	for family in dam_break_3d planetary_mixer_cmc drum_10k drum_100k checkpoint_write checkpoint_read; do \
	  ./$(BUILD_DIR)/bench/partimix_bench --benchmark_counters_tabular=true \
	    --benchmark_filter="^$$family/" || exit 1; \
	done

format:
	find src tests bench -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR)
