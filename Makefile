# gnomon: the two quick-start commands (`make demo`, `make test`) and their helpers.
# SANITIZE=1 builds with ASan+UBSan (Debug) into build/asan instead of build/release.

SANITIZE ?= 0
JOBS ?= $(shell nproc)
ifeq ($(SANITIZE),1)
  BUILD_DIR := build/asan
  CMAKE_ARGS := -DCMAKE_BUILD_TYPE=Debug -DGNOMON_SANITIZE=ON
  # The GL driver's process-lifetime allocations are not our leaks (tests/lsan.supp).
  # use_tls=0: LeakSanitizer's thread tracer crashes reading the thread-local storage of
  # the libraries loaded with tinygltf and Embree (TBB); leaks are checked without TLS roots.
  export LSAN_OPTIONS := suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0:use_tls=0
  export UBSAN_OPTIONS := print_stacktrace=1:halt_on_error=1
else
  BUILD_DIR := build/release
  CMAKE_ARGS := -DCMAKE_BUILD_TYPE=Release
endif
GNOMON := $(BUILD_DIR)/apps/gnomon/gnomon
OUT ?= out
# `make install`: gnomon into PREFIX/bin (and the library for find_package); the default needs
# no root and ~/.local/bin is on PATH in Debian's default profile once it exists.
PREFIX ?= $(HOME)/.local

.PHONY: all deps configure build demo test install format clean
all: build

deps:
	@scripts/deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) $(CMAKE_ARGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@scripts/demo.sh $(GNOMON) $(OUT)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX) >/dev/null
	@echo "installed $(PREFIX)/bin/gnomon"

format:
	@git ls-files --cached --others --exclude-standard '*.cpp' '*.h' | xargs clang-format -i

clean:
	@rm -rf build out
