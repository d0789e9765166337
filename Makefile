# PathLab: `make run` sets up, builds and renders the Cornell box; `make test` runs every test.
BUILD ?= build
JOBS ?= $(shell nproc)

.PHONY: run build test deps clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
	@cmake --build $(BUILD) -j $(JOBS)

run: build
	@scripts/run-default-scene.sh $(BUILD)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD)
