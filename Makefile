# glintlab: the two set-up commands (README) and a few conveniences.
#   make demo   install missing Debian packages, build (Release), compare every method on the default scene
#   make test   install missing Debian packages, build (Release), run the whole suite through ctest
#   make bench-tables  time generating and loading each precomputed table (Google Benchmark; not in test)
#   make bench-normal-maps  time the procedural normal-map generators at their largest inputs (the same)
.PHONY: all deps build demo test bench bench-tables bench-normal-maps clean

BUILD := build/release
JOBS ?= $(shell nproc)

all: build

deps:
	@tools/install-deps.sh

build: deps
	cmake --preset release >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/glintlab compare --scene builtin:spheres --methods all -o out/demo

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD)/glintlab bench --scene builtin:spheres --methods all --width 1920 --height 1080

bench-tables: build
	$(BUILD)/benchmarks/bench_tables

bench-normal-maps: build
	$(BUILD)/benchmarks/bench_normal_maps

clean:
	rm -rf build out
