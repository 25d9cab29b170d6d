# molchaos top-level driver. On a fresh Debian 12 machine, as root:
#   make reproduce   regenerate the paper's results into results/
#   make test        build and run the fast test set (what CI runs)
#   make help        every target, one line each
# The targets that build or run something (configure, build, build-app, reproduce, test,
# test-all, bench, format, deps) first check that the Debian packages they need are installed:
# as root they install the missing ones (apt-get update, then apt-get install, naming them
# first); as another user they name the missing ones with the command for an administrator, and
# stop. help, packages and clean need and install nothing.

BUILD     ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
QUICK     ?= 0
# Extra CMake settings, e.g. CMAKE_ARGS=-DMOLCHAOS_WITH_MPI=OFF (no MPI driver).
CMAKE_ARGS ?=
RESULTS   ?= results

# The Debian packages, by what needs them.
# Build the suite (configure needs every library, pybind11 and python3-dev; sympy derives the
# exact coefficients at build time) and run the program (gnuplot draws the figures, python3 runs
# the README check after `make reproduce`): build, build-app, configure, reproduce.
BUILD_PACKAGES := cmake g++ make git pkg-config ca-certificates python3 python3-sympy \
            libgsl-dev libeigen3-dev libboost-test-dev libboost-iostreams-dev \
            libboost-filesystem-dev libboost-system-dev libgnuplot-iostream-dev gnuplot-nox \
            libcli11-dev nlohmann-json3-dev libfmt-dev libhdf5-dev pybind11-dev python3-dev
# The tests on top: the MPI driver and its tests (OpenMPI), the benchmarks compiled with
# everything else (Google Benchmark), the Python module's tests and examples (numpy, pandas and
# h5py are also what `import molchaos` needs), REPORT.html in a headless browser (chromium).
TEST_PACKAGES := libopenmpi-dev openmpi-bin libbenchmark-dev chromium \
            python3-numpy python3-pandas python3-pytest python3-scipy python3-matplotlib \
            python3-h5py python3-ase
# `make bench` on top of the build: Google Benchmark and callgrind (bench/engine_counts.sh).
BENCH_PACKAGES := libbenchmark-dev valgrind
# `make format`, a developer's step, not part of PACKAGES.
FORMAT_PACKAGES := clang-format git

# The one list for every target but format (README.md quotes it; `make -s packages` prints it).
PACKAGES := $(BUILD_PACKAGES) $(TEST_PACKAGES) $(filter-out $(TEST_PACKAGES),$(BENCH_PACKAGES))

# What the targets on the command line need (`make` alone builds); `make deps` checks PACKAGES.
GOALS    := $(or $(MAKECMDGOALS),all)
BUILDING := $(filter all configure build build-app reproduce test test-all bench $(BUILD)/%,$(GOALS))
NEEDED   := $(sort $(if $(BUILDING),$(BUILD_PACKAGES)) \
                   $(if $(filter test test-all,$(GOALS)),$(TEST_PACKAGES)) \
                   $(if $(filter bench,$(GOALS)),$(BENCH_PACKAGES)) \
                   $(if $(filter format,$(GOALS)),$(FORMAT_PACKAGES)) \
                   $(if $(filter deps,$(GOALS)),$(PACKAGES)))

# The packages whose presence changes what CMake configures (the MPI driver and its tests, the
# benchmarks): a build configured without them is configured again once they are installed.
CONFIGURE_OPTIONAL := libopenmpi-dev openmpi-bin libbenchmark-dev

.PHONY: all help deps packages configure build build-app test test-all reproduce bench clean format

all: build

help:
	@echo "make reproduce   the paper's figures, REPORT.md and REPORT.html into $(RESULTS)/ (QUICK=1: a first look)"
	@echo "make test        build everything and run the fast tests (ctest -LE slow; what CI runs)"
	@echo "make test-all    build everything and run every test, the slow ones too"
	@echo "make bench       engine and quadrature benchmarks into $(RESULTS)/bench/"
	@echo "make build       configure (CMake, Release) into $(BUILD)/ and build everything (the default)"
	@echo "make build-app   build only the program, $(BUILD)/molchaos"
	@echo "make configure   run CMake again into $(BUILD)/ (CMAKE_ARGS=... passes settings on)"
	@echo "make format      clang-format every C++ file in place (needs clang-format)"
	@echo "make deps        check, and as root install, every package of PACKAGES"
	@echo "make packages    print PACKAGES, the Debian packages of every target but format, on one line"
	@echo "make clean       remove $(BUILD)/"
	@echo "make help        this list"

# The list, one line (for an administrator: apt-get install --no-install-recommends $(make -s packages)).
packages:
	@echo $(PACKAGES)

deps:
	@missing=""; for p in $(NEEDED); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed$$" || missing="$$missing $$p"; \
	done; \
	if [ -z "$$missing" ]; then echo "[deps] all $(words $(NEEDED)) Debian packages needed here are present"; exit 0; fi; \
	echo "[deps] missing Debian packages:$$missing"; \
	if [ "$$(id -u)" != 0 ]; then \
	  echo "[deps] not root: an administrator installs them with" >&2; \
	  echo "[deps]   sudo apt-get install --no-install-recommends$$missing" >&2; \
	  echo "[deps] (all of PACKAGES at once: sudo apt-get install --no-install-recommends \$$(make -s packages))" >&2; \
	  exit 1; \
	fi; \
	echo "[deps] running apt-get update, then apt-get install --no-install-recommends$$missing"; \
	export DEBIAN_FRONTEND=noninteractive; \
	apt-get update -q && apt-get install -y -q --no-install-recommends $$missing

# The CMAKE_ARGS of the last configure, rewritten when they differ, so that other ones (make
# CMAKE_ARGS=...) configure again, where an existing build would keep its settings without a word.
ifneq ($(BUILDING),)
ifneq ($(file <$(BUILD)/cmake-args),$(strip $(CMAKE_ARGS)))
$(shell mkdir -p $(BUILD) && echo '$(strip $(CMAKE_ARGS))' > $(BUILD)/cmake-args)
endif
endif
$(BUILD)/cmake-args:
	@mkdir -p $(BUILD); echo '$(strip $(CMAKE_ARGS))' > $@

# Which of CONFIGURE_OPTIONAL are installed, rewritten (after deps) only when that changes.
$(BUILD)/optional-packages: deps
	@mkdir -p $(BUILD); \
	found=$$(dpkg-query -W -f='$${Package} $${Status}\n' $(CONFIGURE_OPTIONAL) 2>/dev/null | \
	         awk '/ok installed$$/ {printf "%s ", $$1}'); \
	[ "$$(cat $@ 2>/dev/null)" = "$$found" ] || echo "$$found" > $@

$(BUILD)/CMakeCache.txt: $(BUILD)/cmake-args $(BUILD)/optional-packages
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)
	@touch $@  # cmake leaves an unchanged cache's time as it was

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# Only the program (what `reproduce` needs), not the tests and benchmarks.
build-app: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target molchaos

# Fast set: everything not labelled 'slow'. Stays under ~10 minutes on 2 cores.
test: build
	cd $(BUILD) && ctest -LE slow --output-on-failure -j $(JOBS)

test-all: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# After a full reproduction, the README's quoted findings are checked against the new report
# (tests/docs/readme_findings.py): a number that moved is named, so the README can follow.
reproduce: build-app
	@mkdir -p $(RESULTS)
	$(BUILD)/molchaos reproduce --out $(RESULTS) $(if $(filter 1,$(QUICK)),--quick,)
	@if [ "$(QUICK)" != 1 ]; then python3 tests/docs/readme_findings.py README.md $(RESULTS)/REPORT.md || \
	  echo "[reproduce] README.md's findings need updating from $(RESULTS)/REPORT.md"; fi

bench: build
	@mkdir -p $(RESULTS)/bench
	@for b in $(BUILD)/bench/bench_*; do [ -x "$$b" ] || continue; echo "== $$b"; \
	  "$$b" --benchmark_out=$(RESULTS)/bench/$$(basename $$b).json --benchmark_out_format=json || exit 1; done
	$(BUILD)/molchaos bench --theory --simulation --out $(RESULTS)/bench
	@echo "== engine work per collision (callgrind counts, load-independent; about 5 minutes)"
	bench/engine_counts.sh $(BUILD) | tee $(RESULTS)/bench/engine_counts.txt

format: deps
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD)
