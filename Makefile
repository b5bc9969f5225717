# The set-up commands of the README: `make demo` and `make test`. Bare `make` lists them.
.PHONY: help demo serve test test-asan bench build configure deps format clean screenshots

help:
	@echo "make demo       install what is missing, build ncvm, run every bundled example (out/demo/)"
	@echo "make serve      build, start the web viewer (http://127.0.0.1:8765/)"
	@echo "make test       build everything with the tests, run them (ctest)"
	@echo "make test-asan  the same tests under AddressSanitizer + UBSan (clang)"
	@echo "make bench      build and run the benchmarks (docs/performance.md)"
	@echo "make build      build everything (Release, build/release)"
	@echo "make format     clang-format the C++ sources"
	@echo "make screenshots build, retake the web viewer's pictures in docs/images/"
	@echo "make deps       install the Debian packages and the npm packages (web viewer, LSP tests, VS Code extension)"
	@echo "make clean      remove build/"

deps:
	@scripts/install-deps

configure: deps
	@cmake --preset release >/dev/null

build: configure
	@cmake --build --preset release

# The demo runs only ncvm: it builds only ncvm (not the tests, benchmarks or the server).
demo: configure
	@cmake --build --preset release --target ncvm
	@scripts/demo

serve: build
	@build/release/bin/ncvm serve

test: build
	@ctest --preset release

test-asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan
	@ctest --preset asan

bench: build
	@bench/run-benchmarks

screenshots: build
	@NCVM_BIN=build/release/bin/ncvm NCVM_WEB=build/release/web node scripts/viewer-screenshots.mjs

format:
	@find src tests bench -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf build
