# molchaos top-level driver. On a fresh Debian 12 machine, as root:
#   make reproduce   regenerate the paper's results into results/
#   make test        build and run the fast test set (what CI runs)
# Every target first installs the Debian packages that are missing (and says which).

BUILD     ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
QUICK     ?= 0
# Extra CMake settings, e.g. CMAKE_ARGS=-DMOLCHAOS_WITH_MPI=OFF (no MPI driver).
CMAKE_ARGS ?=
RESULTS   ?= results

# The one list of Debian packages the project needs (build, test, figures, benchmarks, MPI).
PACKAGES := cmake g++ make git pkg-config ca-certificates python3 python3-sympy \
            libgsl-dev libeigen3-dev libboost-test-dev libboost-iostreams-dev \
            libboost-filesystem-dev libboost-system-dev libgnuplot-iostream-dev gnuplot-nox \
            libcli11-dev nlohmann-json3-dev libfmt-dev libbenchmark-dev \
            libopenmpi-dev openmpi-bin valgrind chromium \
            pybind11-dev python3-dev python3-numpy python3-pandas python3-pytest python3-scipy \
            python3-matplotlib libhdf5-dev python3-h5py python3-ase

.PHONY: all deps packages configure build build-app test test-all reproduce bench clean format

all: build

# The list, one line (for an administrator: apt-get install --no-install-recommends $(make -s packages)).
packages:
	@echo $(PACKAGES)

deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed$$" || missing="$$missing $$p"; \
	done; \
	if [ -z "$$missing" ]; then echo "[deps] all $(words $(PACKAGES)) Debian packages present"; exit 0; fi; \
	echo "[deps] missing Debian packages:$$missing"; \
	if [ "$$(id -u)" != 0 ]; then echo "[deps] run as root (or install them with apt-get) and retry" >&2; exit 1; fi; \
	echo "[deps] running apt-get update, then apt-get install --no-install-recommends$$missing"; \
	export DEBIAN_FRONTEND=noninteractive; \
	apt-get update -q && apt-get install -y -q --no-install-recommends $$missing

# The CMAKE_ARGS of the last configure, rewritten when they differ, so that other ones (make
# CMAKE_ARGS=...) configure again, where an existing build would keep its settings without a word.
ifneq ($(file <$(BUILD)/cmake-args),$(strip $(CMAKE_ARGS)))
$(shell mkdir -p $(BUILD) && echo '$(strip $(CMAKE_ARGS))' > $(BUILD)/cmake-args)
endif
$(BUILD)/cmake-args:
	@mkdir -p $(BUILD); echo '$(strip $(CMAKE_ARGS))' > $@

$(BUILD)/CMakeCache.txt: $(BUILD)/cmake-args | deps
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

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD)
