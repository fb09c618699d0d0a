# widestereo: the whole workflow for a newcomer.
#   make demo   install what is missing, build, run the whole pipeline
#   make test   install what is missing, build, run every test with ctest
#   make test-asan  decoders, threads and models under AddressSanitizer + UBSan (build-asan/)
#   make fuzz   every libFuzzer target for FUZZ_SECONDS each (clang, build-fuzz/)

SHELL := /bin/bash
BUILD ?= build
JOBS ?= $(shell nproc)
LCM_URL ?=
ASAN_BUILD ?= build-asan
ASAN_OPT ?= -O1 -g1 -DNDEBUG
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

# Every Debian package the project uses (build, tests, demo, lcm-spy, plots,
# the benchmarks against mrcal: bench/real, bench/fisheye, and stereo-view's
# server, its 3-D view and the page's tests in headless Chromium).
DEB_PACKAGES := build-essential cmake pkg-config default-jdk-headless \
  liblcm-dev liblcm-bin liblcm-java libjchart2d-java \
  libopencv-dev libopencv-contrib-dev opencv-doc \
  libceres-dev libeigen3-dev libpcl-dev libaravis-dev \
  libgtest-dev libcli11-dev libyaml-cpp-dev nlohmann-json3-dev \
  gnuplot-nox iproute2 tmux xvfb clang libclang-rt-14-dev python3 python3-yaml time \
  libsodium-dev mrcal python3-mrcal python3-opencv pybind11-dev python3-pybind11 python3-numpy \
  python3-pytest libjs-three chromium chromium-driver python3-selenium

.PHONY: deps build build-tests built test test-asan fuzz demo spy clean

deps:
	@missing=$$(for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing" $$missing; \
	  $(SUDO) apt-get update && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing; \
	else echo "make deps: all $(words $(DEB_PACKAGES)) Debian packages present"; fi

# Everything, the benchmarks (bench/) included; `make test` builds what the
# tests run and leaves the benchmarks out.
build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS) --target all bench

build-tests: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j$(JOBS)

# What demo and spy need: CMake's configure only when there is no build yet
# (cmake --build configures again by itself when a CMakeLists.txt changed),
# and of the build's output only what it does, not the targets up to date.
built: deps
	@[ -f $(BUILD)/CMakeCache.txt ] || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	@set -o pipefail; cmake --build $(BUILD) -j$(JOBS) | { grep -v -e 'Built target' -e 'Consolidate compiler' -e 'ing directory' || true; }

test: build-tests
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 600

# The tests of the asan_checks target (tests/CMakeLists.txt: decoders and
# readers, threads, models), the processes they run included, built with
# -fsanitize=address,undefined: any report fails the test that triggered it.
# The tests of targets not built are left out (ctest lists them *_NOT_BUILT),
# and those that run what asan_checks does not build: the Java, Python and
# browser tests and the install example.
# ASAN_OPT: -O1 -g1 (line tables for the reports), not RelWithDebInfo's
# -O2 -g: calib/solver/problem.cpp, the heaviest file, took 363 s of CPU so
# against more than 407 s (stopped unfinished); and that file is compiled
# without the sanitizers (common/calib/CMakeLists.txt). docs/reliability.md has the
# figures: about 13 min to build and 3 to test on two idle cores.
test-asan: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWS_SANITIZE=ON -DWS_BUILD_BENCH=OFF \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(ASAN_OPT)" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(ASAN_OPT)"
	cmake --build $(ASAN_BUILD) -j$(JOBS) --target asan_checks
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j$(JOBS) --timeout 1200 -E '_NOT_BUILT$$|^java_|^python_|^install_example$$|^view_page_'


fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWS_FUZZ=ON \
	  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
	cmake --build $(FUZZ_BUILD) -j$(JOBS)
	scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

demo: built
	scripts/demo.sh

# lcm-spy with our types decoded. Debian's /usr/bin/lcm-spy passes -Xincgc,
# which Java 17 refuses, so start the Spy class directly.
spy: built
	java -cp /usr/share/java/lcm.jar:/usr/share/java/jchart2d.jar:$(BUILD)/share/java/lcmtypes_widestereo.jar \
	  lcm.spy.Spy $(if $(LCM_URL),--lcm-url=$(LCM_URL))

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD)
