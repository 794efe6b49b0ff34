# vcsph: a thin wrapper around CMake (design §6).
BUILD ?= build
ASAN_BUILD ?= build-asan
MPI_BUILD ?= build-mpi
JOBS ?= $(shell nproc)
CASE ?= cases/default.ini
RUN_DIR ?= out/default

.PHONY: all deps build run test test-long sanitize test-mpi bench clean

all: build

deps:
	@tools/install-deps

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The default case: a short sloshing run, then plots of its time series.
run: deps
	@$(MAKE) --no-print-directory build
	$(BUILD)/vcsph run $(CASE) -o $(RUN_DIR) --overwrite
	$(BUILD)/vcsph plot $(RUN_DIR)
	@echo "vcsph: output in $(RUN_DIR) (open $(RUN_DIR)/snapshots.xmf in ParaView; plots in $(RUN_DIR)/images)"

# The tests a newcomer runs (under 5 minutes on 2 idle cores), less the long physics runs
# (labels `long` and `slow`, tests/CMakeLists.txt), which `make test-long` runs and CI too.
test: deps
	@$(MAKE) --no-print-directory build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE 'long|slow'

test-long: deps
	@$(MAKE) --no-print-directory build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -L 'long|slow'

# The same tests under AddressSanitizer + UndefinedBehaviorSanitizer, warnings as errors
# (optimised, so that the integration runs take seconds, not minutes), less the long physics
# runs (label `long`, tests/CMakeLists.txt), whose code paths shorter tests take too and which
# would add some 25 minutes under the sanitizers.
sanitize: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVCSPH_SANITIZE=ON -DVCSPH_CHECKS=ON -DVCSPH_WERROR=ON
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS) -LE long

# The MPI layer's tests (docs/mpi.md) in a build of their own with -DVCSPH_MPI=ON; installs
# Open MPI and parallel HDF5 where missing. Only the MPI targets are built.
test-mpi:
	@tools/install-deps --mpi
	cmake -S . -B $(MPI_BUILD) -DCMAKE_BUILD_TYPE=Release -DVCSPH_MPI=ON $(CMAKE_FLAGS)
	cmake --build $(MPI_BUILD) -j $(JOBS) --target mpi_tests
	ctest --test-dir $(MPI_BUILD) -L mpi --output-on-failure

bench: deps
	@$(MAKE) --no-print-directory build
	$(BUILD)/bench_step 30 delta delta-plus-ale:none delta-plus-ale delta-ale
	$(BUILD)/bench_scaling_2d 1e6
	$(BUILD)/bench_scaling_3d 1e6
	$(BUILD)/checkpoint_io $(BUILD)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD)
