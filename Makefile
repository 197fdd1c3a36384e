# SPDX-License-Identifier: Apache-2.0
# hmcr: the two commands of the README (`make run`, `make test`) and their helpers.
BUILD    ?= build
TYPE     ?= Release
JOBS     ?= $(shell nproc)
SANITIZE ?= OFF

# Debian 12 packages hmcr builds, tests and plots with, each used by a target, a test or a script
# (README.md: "Dependencies" says why each is there; docs/decisions.md what was left out).
DEPS := g++ cmake make libpng-dev libembree-dev libopenmesh-dev libvtk9-dev libeigen3-dev \
        libhwy-dev libtinygltf-dev libtbb-dev libexpat1-dev libcli11-dev nlohmann-json3-dev \
        libfmt-dev \
        libopenmpi-dev openmpi-bin libgtest-dev libboost-dev zlib1g-dev clang libclang-rt-14-dev \
        clang-format clang-tidy dpkg-dev python3 python3-matplotlib xvfb xauth \
        pybind11-dev python3-dev python3-numpy python3-pytest \
        texlive-latex-recommended

SANITIZE_BUILD ?= build-sanitize
TSAN_BUILD ?= build-tsan
TIDY_BUILD ?= build-tidy
PREFIX ?= /usr/local
# Debian's Python, which python3-matplotlib serves (another python3 may come first on the PATH).
PLOT_PYTHON ?= /usr/bin/python3

.PHONY: deps view-deps build run install check-without-tests test test-quick test-sanitize \
        test-tsan tidy bench scenes format format-check clean

# Installs only what is missing, so it is quick when everything is present.
deps:
	@missing=$$(for p in $(DEPS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing $$missing"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq && apt-get install -y -qq --no-install-recommends $$missing; \
	fi

# What looking at results takes, not the build: ParaView, and Xvfb (with the xauth that xvfb-run
# needs) to run it without a display. Without recommended packages: paraview recommends
# python3-paraview, which conflicts with the python3-vtk9 of libvtk9-dev, and apt would remove
# both (and break the build) to install it. Installs nothing where apt would still remove a
# package.
VIEW_DEPS := paraview xvfb xauth
view-deps:
	@missing=$$(for p in $(VIEW_DEPS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-get update -qq || exit 1; \
	  removed=$$(apt-get install -s --no-install-recommends $$missing | sed -n 's/^Remv \([^ ]*\).*/\1/p'); \
	  if [ -n "$$removed" ]; then \
	    echo "make view-deps: installing" $$missing "would remove" $$removed": nothing installed" >&2; \
	    exit 1; \
	  fi; \
	  echo "make view-deps: installing $$missing"; \
	  apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(TYPE) -DHMCR_SANITIZE=$(SANITIZE)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# Builds hmcr alone (not the test suite) and solves the bundled Cornell box: out/cornell.vtp,
# its summary out/cornell.json and out/cornell.pvsm (`paraview --state=out/cornell.pvsm`).
run: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target hmcr
	$(BUILD)/hmcr solve cornell -o out/cornell.vtp

# hmcr alone, installed: PREFIX/bin/hmcr and PREFIX/share/hmcr (the scenes, their generators and
# the plotting script), which the installed program finds beside itself.
install: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target hmcr_installed
	cmake --install $(BUILD) --prefix $(PREFIX)

# hmcr built and installed without what only the tests need (docs/testing.md): NOTESTS_BUILD
# configured with BUILD_TESTING off and GoogleTest and Python made unfindable, then the
# install test's checks on it (tests/install/install_test.sh: installed into a temporary prefix,
# the program solves cornell from the prefix alone).
NOTESTS_BUILD ?= build-notests
check-without-tests: deps
	cmake -S . -B $(NOTESTS_BUILD) -DCMAKE_BUILD_TYPE=$(TYPE) -DBUILD_TESTING=OFF \
	  -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_Python3=ON \
	  -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON
	cmake --build $(NOTESTS_BUILD) -j $(JOBS) --target hmcr_installed
	sh tests/install/install_test.sh . $(NOTESTS_BUILD)

# The whole suite, statistical tests included (label `slow`).
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Everything but the slow statistical tests.
test-quick: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

# The fast suite again under AddressSanitizer and UBSan (clang), and a short run of every fuzz
# target (tests/fuzz): what CI runs after `make test`. Line tables are all a sanitizer report
# needs to name file and line; full debug information would only slow the build.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=clang++ -DHMCR_FUZZ=ON \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG"
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -L fuzz

# The tests that run threads (TSAN_TESTS, by name: docs/testing.md#threadsanitizer says which),
# under ThreadSanitizer (clang). TBB is built from Debian's source with it (scripts/tsan_tbb.sh:
# TSan cannot see the synchronisation inside an uninstrumented TBB); the reports that pass
# through Embree, not instrumented either, are suppressed (tests/tsan.supp says why), and VTK's
# parallel loops run sequentially. A report fails the test. Only the test files that declare one of
# these tests are compiled (CMakeLists.txt, HMCR_TSAN_TESTS).
TSAN_TESTS ?= Thread|LinkCache|AtomicFile\.Concurrent
test-tsan: deps
	scripts/tsan_tbb.sh $(TSAN_BUILD) $(JOBS)
	cmake -S . -B $(TSAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=clang++ -DHMCR_TSAN=ON -DHMCR_TSAN_TESTS='$(TSAN_TESTS)' \
	  -DTBB_DIR=$(abspath $(TSAN_BUILD))/tbb-tsan/lib/cmake/TBB \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG"
	cmake --build $(TSAN_BUILD) -j $(JOBS) --target hmcr_fast_tests
	cd $(TSAN_BUILD) && VTK_SMP_BACKEND_IN_USE=Sequential \
	  TSAN_OPTIONS="second_deadlock_stack=1 suppressions=$(CURDIR)/tests/tsan.supp" \
	  ctest --output-on-failure -j $(JOBS) -R '$(TSAN_TESTS)'

# clang-tidy 14 over every source of hmcr, the tests aside (.clang-tidy: the checks, and why some
# are left out); a finding fails. It reads the unity build's sources, 8 sources each as the
# compiler builds them, so the heavy library headers (VTK, Eigen, nlohmann/json) are parsed once
# for 8 sources; a source's findings are still named by its own file and line. Only CMake's
# configure is needed (compile_commands.json): nothing is built. A second run holds the core's
# functions to 80 lines (readability-function-size): over the sources of radiosity/, rays/ and
# studies/ alone and their own headers, since app/ and trace/ keep longer ones.
TIDY_SIZE_CONFIG := {Checks: '-*,readability-function-size', WarningsAsErrors: '*', \
  HeaderFilterRegex: '(^|/)(radiosity|rays|studies)/[a-z0-9_]+\.(h|cpp)$$', \
  CheckOptions: [{key: readability-function-size.LineThreshold, value: 80}]}
tidy: deps
	cmake -S . -B $(TIDY_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
	  -DBUILD_TESTING=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
	run-clang-tidy-14 -p $(TIDY_BUILD) -j $(JOBS) -quiet
	run-clang-tidy-14 -p $(TIDY_BUILD) -j $(JOBS) -quiet -config="$(TIDY_SIZE_CONFIG)" \
	  'hmcr_(radiosity|rays|studies)\.dir/|/rays/ray_generator\.cpp$$'

# The oracle table, the default solve's rows, then the scaling study on office instances of
# 10^2 ... 10^6 patches: bench/results.json (every row) and bench/scaling.pdf and .png (the
# curves). BENCH_ARGS go to hmcr_bench (e.g. --sequence random).
BENCH_SCENES := $(BUILD)/bench-scenes
BENCH_ARGS ?=
bench: build scenes $(BENCH_SCENES)/office-100k.obj
	$(BUILD)/hmcr_bench --results bench/results.json --scaling $(BENCH_SCENES) $(BENCH_ARGS)
	$(PLOT_PYTHON) scripts/plot_study.py bench/scaling_plot_data.json

$(BENCH_SCENES)/office-100k.obj: scenes/office/generate.py
	python3 scenes/office/generate.py --bays 1 --tile 1.6 --name office-100 --out $(BENCH_SCENES)
	python3 scenes/office/generate.py --bays 2 --tile 0.4 --name office-1k --out $(BENCH_SCENES)
	python3 scenes/office/generate.py --bays 4 --tile 0.2 --name office-10k --out $(BENCH_SCENES)
	python3 scenes/office/generate.py --bays 13 --tile 0.2 --name office-100k --out $(BENCH_SCENES)

# Scenes too large for git, generated on demand by their scripts (about 30 s).
scenes: scenes/office/office.obj
scenes/office/office.obj: scenes/office/generate.py
	python3 scenes/office/generate.py

format: deps
	clang-format -i $$(git ls-files '*.cpp' '*.h')

# Fails, naming each file and line, where a source differs from .clang-format (what CI checks).
format-check: deps
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.h')

# The license line at the top of every tracked source that lacks it (docs/decisions.md#license;
# git add a new file first). The docs test Docs.EverySourceNamesItsLicense checks them.
.PHONY: spdx
spdx:
	python3 tests/docs/check_spdx.py . --add

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(TSAN_BUILD) $(TIDY_BUILD) $(NOTESTS_BUILD)
