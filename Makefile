# PathLab: `make run` sets up, builds and renders the Cornell box; `make test` runs every test.
BUILD ?= build
# The cores to build with: nproc on Linux, sysctl on macOS.
JOBS ?= $(shell nproc 2>/dev/null || sysctl -n hw.ncpu 2>/dev/null || echo 2)
# Built for this machine's instruction set: a build here runs here (NATIVE=OFF for a build that
# runs elsewhere). Images are the same either way (framework/CMakeLists.txt).
NATIVE ?= ON
# Warnings in PathLab's own code are errors with WARNINGS_AS_ERRORS=ON, as CI builds (.ci/run);
# off by default, so that a newer compiler's new warning does not stop a student's build.
WARNINGS_AS_ERRORS ?= OFF

.PHONY: run configure build test test-labs test-slow grade report sweep inspect pick-test warptest strategies convergence reference bench profile \
        deps clean \
        handouts handouts-html student-release gradescope

# The student release has no solutions/: there the lab tests (ctest label `labs`) check your own
# labs/, which fail until you finish them, so `make test` leaves them to `make test-labs`.
TEST_EXCLUDED = slow$(if $(wildcard solutions/),,|labs)

# The packages, installed by scripts/install-deps.sh: `make deps` always asks it; the other
# targets only on the first build of a folder (or when the script changed), through a stamp.
DEPS_STAMP = $(BUILD)/.deps-installed

deps:
	@scripts/install-deps.sh
	@mkdir -p $(BUILD) && touch $(DEPS_STAMP)

$(DEPS_STAMP): scripts/install-deps.sh
	@scripts/install-deps.sh
	@mkdir -p $(BUILD) && touch $@

# The build folder configured; a target then builds what it needs (`build`: everything).
configure: $(DEPS_STAMP)
	@cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_NATIVE=$(NATIVE) \
	      -DPATHLAB_WARNINGS_AS_ERRORS=$(WARNINGS_AS_ERRORS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The Cornell box, in a window where there is a display, otherwise headless into an image file:
# the reference solution of lab 3 in the kit; your labs/ (lab 1, or LAB=uniform and so on) in
# the student release. It builds the viewer and the labs alone: the first image comes before the
# grader, the tests and the mutants are built (by the targets that need them).
run: configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@scripts/run-default-scene.sh $(BUILD) $(LAB)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE '$(TEST_EXCLUDED)'

# The lab tests: each lab's furnaces and mirror furnace, its NaN check, its agreement with the
# grader's stored reference of the VI2 box and its view through glass and in a mirror (`ctest -L
# lab2` for one). It builds their program alone, not the kit's own tests.
test-labs: configure
	@cmake --build $(BUILD) -j $(JOBS) --target test_estimators
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L labs

# What `make grade` runs: the grader and the viewer around labs/, which renders for it.
GRADER_TARGETS = grader viewer

# Grade the labs in labs/ (all of them; LAB=uniform for one). VARIANT=DIR grades on your own
# variant's scenes too, from the folder your instructor sent you (grader --variant).
grade: configure
	@cmake --build $(BUILD) -j $(JOBS) --target $(GRADER_TARGETS)
	cd $(BUILD) && ./grader $(if $(LAB),--lab $(LAB)) $(if $(VARIANT),--variant $(abspath $(VARIANT)))

# Grade them and write lab-report.md: your notebook's figures (frame rate, noise, efficiency) and
# the ratios between labs, beside the reference solutions', and the plots of make sweep (below).
report: configure
	@cmake --build $(BUILD) -j $(JOBS) --target $(GRADER_TARGETS)
	cd $(BUILD) && ./grader --report $(CURDIR)/lab-report.md

# Your own lab rendered at a range of one parameter's values, with CSV and PNG plots (frame rate,
# noise, efficiency) beside the handout's figures, into $(BUILD)/sweep/LAB-PARAM/ (scripts/sweep.py):
# LAB=roulette (the default) sweeps continueProb, LAB=branching, uniform or importance maxDepth,
# LAB=glossy PARAM=glossy-exponent the Phong exponent of veach_plates' plates.
# VALUES="0.1 0.5 0.9" for other values, SIZE=256 and SPP=64 for another render. The options are
# checked before anything is configured, built or written.
SWEEP_OPTIONS = --lab='$(LAB)' --param='$(PARAM)' --values='$(VALUES)' --size='$(SIZE)' --spp='$(SPP)'
sweep:
	@python3 scripts/sweep.py --check $(SWEEP_OPTIONS)
	@$(MAKE) --no-print-directory configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@python3 scripts/sweep.py --build $(BUILD) $(SWEEP_OPTIONS)

# One pixel's samples through your lab, path by path (viewer --inspect): each vertex's material,
# the ray that arrived, the emission and direct light added, your throughput, the component you
# picked and the probability you divided by, the roulette draw; beside the reference solution's
# on the same random numbers, with the first vertex where they part, where the kit has it (the
# student release has no solutions: there it shows your lab's paths alone). X and Y name the
# pixel of the 512x512 Cornell box (0 0 the top left); LAB=roulette for another lab (default
# branching), SAMPLES=16 for more samples, ARGS="--continue-prob 0.8" for other parameters. A lab
# that samples a glossy lobe (the lab list's fourth field) is inspected on veach_plates at
# continueProb 0.8, the scene make run shows it on.
LOBE_LABS := $(shell awk '!/^[ \t]*\#/ && NF == 4 {print $$1}' framework/lab_list.txt)
INSPECT_SCENE = $(if $(filter $(LAB),$(LOBE_LABS)),models/veach_plates.ecs --continue-prob 0.8,models/cornell_box_VI2_Specular.ecs)
inspect: configure
	@test -n "$(X)" -a -n "$(Y)" || { echo "make inspect: give the pixel, e.g. make inspect LAB=roulette X=30 Y=256" >&2; exit 2; }
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@cd $(BUILD) && ./viewer -c $(INSPECT_SCENE) --lab $(or $(LAB),branching) --inspect $(X) $(Y) \
	    --inspect-samples $(or $(SAMPLES),8) $(ARGS)

# The pick test of labs 2-4 (viewer --pick-test): how often the lab went on by each component at
# each material of mixed_surfaces, against the probability it divided by; a few seconds.
PICK_TEST_SCENE = models/mixed_surfaces.ecs
pick-test: configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@cd $(BUILD) && ./viewer -c $(PICK_TEST_SCENE) --lab $(or $(LAB),importance) --size 64 64 \
	    --continue-prob 0.8 --pick-test $(ARGS)

# The warp test of lab 5's lobe (viewer --warp-test): a million directions from your sampleLobe at
# each of three exponents, counted over the sphere against your lobePdf (chi-square); the
# picture, observed beside expected, into $(BUILD)/warptest.png. A few seconds.
warptest: configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@cd $(BUILD) && ./viewer --warp-test --lab $(or $(LAB),glossy) --warp-image warptest.png $(ARGS)

# Lab 6's three-panel figure, after Veach's (viewer --strategy-figure): veach_plates rendered by
# your lab with the light strategy alone, the lobe strategy alone and both, side by side, into
# $(BUILD)/strategies.png, and each one's noise figure printed. A few seconds.
STRATEGY_SCENE = models/veach_plates.ecs
strategies: configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@cd $(BUILD) && ./viewer -c $(STRATEGY_SCENE) --lab $(or $(LAB),mis) --continue-prob 0.8 \
	    --size 320 240 --spp $(or $(SPP),16) --strategy-figure strategies.png $(ARGS)

# The error-versus-time plot of your four labs, as handouts/figures/convergence.png shows the
# reference solutions': each lab rendered headless at increasing spp (SPP="4 16 64" for others)
# against the grader's stored references of the VI2 box, CSV and PNG into $(BUILD)/convergence/
# (scripts/convergence.py; under a minute on 2 cores). make report shows it beside the sweeps.
convergence:
	@python3 scripts/convergence.py --check --spp='$(SPP)'
	@$(MAKE) --no-print-directory configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@python3 scripts/convergence.py --build $(BUILD) --spp='$(SPP)'

# The converged image the window's convergence plot measures against, for the VI2 box at the
# window's default size: $(BUILD)/references/cornell_box_VI2_Specular.512x512.exr, 4096 spp of
# lab 4 at continueProb 0.8, about 8 minutes on 2 cores (scripts/make-reference.sh). The window
# finds it there; REFERENCE_SPP=1024 for a quicker, noisier one.
REFERENCE_SPP ?= 4096
reference: configure
	@cmake --build $(BUILD) -j $(JOBS) --target viewer
	@scripts/make-reference.sh $(BUILD) $(REFERENCE_SPP)

# Only the HTML pages (self-contained, in $(BUILD)/handouts/), from the figures as they are.
handouts-html:
	python3 handouts/tools/make_html.py --out $(BUILD)/handouts

clean:
	rm -rf $(BUILD)

# The targets below need the reference solutions: the student release, which has none, says so.
ifeq ($(wildcard solutions/),)
test-slow bench profile handouts student-release gradescope:
	@echo "make $@: needs the reference solutions (solutions/), which the student release does not have" >&2
	@exit 2
else

# The long validations (ctest label `slow`): mutants that need the frame-rate check, and 200
# gradings of correct labs to measure the grader's false-fail rate.
test-slow: build
	cd $(BUILD) && ctest --output-on-failure -L slow

# PathLab's speed beside Embree's raw ray traversal and Embree's own pathtracer: one table per
# scene (apps/bench; `./bench --help`). BENCH_ARGS="--json bench.json" keeps the figures as JSON.
# Timings are only meaningful on an otherwise idle machine.
bench: build
	cd $(BUILD) && ./bench $(BENCH_ARGS)

# Where a sample's time goes: each reference solution at 1 thread under perf, attributed to
# Embree, each framework function, the lab, libm and the rest (apps/bench/profile_solutions.py;
# needs perf: apt-get install linux-perf). PROFILE_ARGS="--markdown" for the README's table.
profile: build
	python3 apps/bench/profile_solutions.py --build $(BUILD) $(PROFILE_ARGS)

# The handouts' figures, remade from the reference solutions and timed on this machine (6 to 10
# minutes on 2 cores, more when busy; run it when the machine is otherwise idle), then their
# HTML pages.
handouts: build
	python3 handouts/tools/make_figures.py --build $(BUILD)
	python3 handouts/tools/make_inspector_figures.py --build $(BUILD)
	python3 handouts/tools/make_html.py --out $(BUILD)/handouts

# The student release, $(BUILD)/pathlab-student.tar.gz: the kit without solutions/, the tests and
# tools built on them, the instructor's hidden scenes and documents or history, with
# README-student.md as its README (docs/instructor-guide.md: The student release).
# RUBRIC=FILE: the release carries the instructor's rubric, the files of the public scenes it
# names (tracked by git or not) and references that fit it (measured again by the grader where
# the kit's, or REFERENCES=DIR's, do not), and says so (docs/instructor-guide.md).
student-release: $(if $(RUBRIC),configure)
	$(if $(RUBRIC),@cmake --build $(BUILD) -j $(JOBS) --target grader viewer)
	@python3 scripts/package_kit.py student-release $(BUILD)/pathlab-student.tar.gz \
	    $(if $(RUBRIC),--rubric '$(RUBRIC)' --build '$(BUILD)') \
	    $(if $(REFERENCES),--references '$(REFERENCES)')

# The Gradescope autograder, $(BUILD)/autograder.zip: the whole kit, with setup.sh and
# run_autograder from scripts/gradescope/ (docs/instructor-guide.md: Gradescope).
gradescope:
	@python3 scripts/package_kit.py gradescope $(BUILD)/autograder.zip
endif
