# The two set-up commands of the README: `make demo` and `make test`.
.PHONY: demo serve test test-asan bench build deps format clean

deps:
	@scripts/install-deps

build: deps
	@cmake --preset release >/dev/null
	@cmake --build --preset release

demo: build
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

format:
	@find src tests bench -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf build
