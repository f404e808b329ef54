# gnomon: the two quick-start commands (`make demo`, `make test`) and their helpers.
# SANITIZE=1 builds with ASan+UBSan (Debug) into build/asan instead of build/release.
# `make web` builds the web page into build/web (docs/web.md); `make test` builds it too and
# runs its browser tests with the rest.

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
# The web page: Emscripten's build tree, and the page itself. Emscripten's tools run on Node
# and need Debian's Node modules (acorn), which a Node from elsewhere does not search.
WEB_BUILD := build/web-build
WEB_OUT := build/web
WEB_ENV := NODE_PATH=/usr/share/nodejs

.PHONY: all deps configure build demo test web install format clean
all: build

deps:
	@scripts/deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) $(CMAKE_ARGS) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	@scripts/demo.sh $(GNOMON) $(OUT)

# A page that did not build fails the web tests, which say why; the other tests run anyway.
test: build
	@$(MAKE) --no-print-directory web || echo "gnomon: make web failed; the web tests will fail" >&2
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# build/web/.built marks a page the last `make web` finished: the browser tests check it.
web:
	@rm -f $(WEB_OUT)/.built
	@scripts/web-deps.sh
	@[ -f $(WEB_BUILD)/CMakeCache.txt ] || \
	    $(WEB_ENV) emcmake cmake -S . -B $(WEB_BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@$(WEB_ENV) cmake --build $(WEB_BUILD) -j $(JOBS)
	@touch $(WEB_OUT)/.built

install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX) >/dev/null
	@echo "installed $(PREFIX)/bin/gnomon"

format:
	@git ls-files --cached --others --exclude-standard '*.cpp' '*.h' | xargs clang-format -i

clean:
	@rm -rf build out
