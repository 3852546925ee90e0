# glintlab: the two set-up commands (README) and a few conveniences.
#   make demo   install the missing Debian packages the glintlab binary needs, build only it (build/demo),
#               compare every method on the default scene and write the HTML report (tools/demo.sh)
#   make test   install missing Debian packages, build (Release, the clang fuzz targets and make demo's
#               unity build), run the whole suite through ctest, then the fuzz targets' smoke pass
#               (docs/fuzzing.md)
#   make view   open the viewer on the default scene (needs a display; docs/viewer.md)
#   make fuzz   run every fuzz target for FUZZ_SECONDS each (default 600; docs/fuzzing.md)
#   make bench-tables  time generating and loading each precomputed table (Google Benchmark; not in test)
#   make bench-normal-maps  time the procedural normal-map generators at their largest inputs (the same)
#   make bench-rays  ray queries alone (Embree, no shading) on every built-in scene: rays per second per core
#   make bench-ndf-sampling  a footprint's NDF evaluated and sampled: deng2022's pyramid, yan2016's elements, GGX
#   make ltc-fit-report  fit both LTC tables: generation time and the fit error over the grid (markdown)
.PHONY: all deps build build-fuzz build-demo demo view test fuzz bench bench-tables bench-normal-maps bench-rays bench-ndf-sampling ltc-fit-report clean

BUILD := build/release
FUZZ_BUILD := build/fuzz
FUZZ_SECONDS ?= 600
JOBS ?= $(shell nproc)

all: build

deps:
	@tools/install-deps.sh

build: deps
	cmake --preset release >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

# The fuzz targets need clang with libFuzzer (installed by deps); without clang they are skipped.
build-fuzz: deps
	@if command -v clang++ >/dev/null; then \
	  cmake --preset fuzz >/dev/null && cmake --build $(FUZZ_BUILD) -j $(JOBS); \
	else echo "glintlab: clang++ not found: fuzz targets skipped"; fi

# make demo's binary (a unity build, build/demo), built by make test too: a name that two files
# each define in an anonymous namespace breaks only this build.
build-demo: deps
	cmake --preset demo >/dev/null
	cmake --build --preset demo -j $(JOBS)

demo:
	@JOBS=$(JOBS) tools/demo.sh

view: build
	$(BUILD)/glintlab view --mode split

test: build build-fuzz build-demo
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@if [ -f $(FUZZ_BUILD)/CTestTestfile.cmake ]; then cd $(FUZZ_BUILD) && ctest --output-on-failure -j $(JOBS); fi

fuzz: build-fuzz
	tools/fuzz.sh all $(FUZZ_SECONDS)

bench: build
	$(BUILD)/glintlab bench --scene builtin:spheres --methods all --width 1920 --height 1080

bench-tables: build
	$(BUILD)/benchmarks/bench_tables

bench-normal-maps: build
	$(BUILD)/benchmarks/bench_normal_maps

bench-rays: build
	$(BUILD)/benchmarks/bench_ray_queries

bench-ndf-sampling: build
	$(BUILD)/benchmarks/bench_ndf_sampling

ltc-fit-report: build
	$(BUILD)/benchmarks/ltc_fit_report

clean:
	rm -rf build out
