# PathLab: `make run` sets up, builds and renders the Cornell box; `make test` runs every test.
BUILD ?= build
JOBS ?= $(shell nproc)

.PHONY: run build test test-slow grade deps clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
	@cmake --build $(BUILD) -j $(JOBS)

run: build
	@scripts/run-default-scene.sh $(BUILD)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE slow

# The long validations (ctest label `slow`): mutants that need the frame-rate check, and 200
# gradings of correct labs to measure the grader's false-fail rate.
test-slow: build
	cd $(BUILD) && ctest --output-on-failure -L slow

# Grade the labs in labs/ (all four; LAB=uniform for one).
grade: build
	cd $(BUILD) && ./grader $(if $(LAB),--lab $(LAB))

clean:
	rm -rf $(BUILD)
