# stepwise — build, test and install. `make run` and `make test` first make
# sure ncursesw and Check are present (the `deps` step), so a fresh Debian
# machine goes from nothing to a running lesson or a passing suite.

CC      ?= cc
PREFIX  ?= /usr/local

# One job a core unless the command line says how many (`make -j1`: one at
# a time; any -jN wins). Only the top-level make: a recursive one shares
# its parent's jobs. Not with clean among the goals (`make clean all`).
ifeq ($(MAKELEVEL)$(filter -j%,$(MAKEFLAGS))$(filter clean,$(MAKECMDGOALS)),0)
MAKEFLAGS += -j$(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
endif

BUILD   ?= build
DESTDIR ?=
OPT     ?= -O2 -g

# gcc's -O2 vectoriser only takes loops with no epilogue; the cheap model also
# takes the integrators' elementwise loops (results stay bit-identical).
VECT    = $(shell $(CC) -fvect-cost-model=cheap -Werror -c -x c /dev/null -o /dev/null 2>/dev/null && echo -fvect-cost-model=cheap)
# -fno-math-errno: sqrt compiles to the instruction (no errno branch), so loops
# with a square root vectorise; results are the same bits (not -ffast-math).
MATH    = -fno-math-errno
WARN    = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes
ifeq ($(WERROR),1)
WARN   += -Werror
endif
ifeq ($(FUZZ),1)
OPT     = -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
endif
ifeq ($(SAN),1)
OPT     = -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
LDSAN   = -fsanitize=address,undefined
endif

DATADIR  = $(PREFIX)/share/stepwise
LIBEXECDIR = $(PREFIX)/libexec/stepwise
CPPFLAGS = -Iinclude -Isrc -D_DEFAULT_SOURCE -D_XOPEN_SOURCE=600 -D_XOPEN_SOURCE_EXTENDED \
           -DSW_DATADIR='"$(DATADIR)"' -DSW_LIBEXECDIR='"$(LIBEXECDIR)"'
CFLAGS  ?=
ALL_CFLAGS = -std=c11 $(OPT) $(VECT) $(MATH) $(WARN) $(CFLAGS) -MMD -MP

# Looked up when a recipe runs, i.e. after `deps` has installed them.
CURSES_CFLAGS = $(shell pkg-config --cflags ncursesw 2>/dev/null)
CURSES_LIBS   = $(shell pkg-config --libs ncursesw 2>/dev/null || echo -lncursesw)
CHECK_CFLAGS  = $(shell pkg-config --cflags check 2>/dev/null)
CHECK_LIBS    = $(shell pkg-config --libs check 2>/dev/null || echo -lcheck)
SECCOMP_LIBS  = $(shell pkg-config --libs libseccomp 2>/dev/null || echo -lseccomp)

# Two archives. The tool's: every layer below the front ends
# (docs/architecture.md), util/ included, which the program, the tests and
# the benchmarks link; only tui/ includes ncurses, and cli/ and tui/ are
# linked into the program only. The embedder's, libstepwise.a, installed:
# the engine, the scenes and the sim with the three util modules they use,
# partially linked into one object whose only global names are sw_ ones
# (docs/embedding.md): no grader, no lessons, no jail, no libseccomp.
TUI_SRC  = $(wildcard src/tui/*.c)
HOST_MAIN = $(wildcard src/host/*.c)
CLI_SRC  = $(wildcard src/cli/*.c)
LIB_SRC  = $(filter-out $(TUI_SRC) $(CLI_SRC) $(HOST_MAIN),$(wildcard src/*/*.c))
LIB_OBJ  = $(LIB_SRC:%.c=$(BUILD)/%.o)
TUI_OBJ  = $(TUI_SRC:%.c=$(BUILD)/%.o) $(CLI_SRC:%.c=$(BUILD)/%.o)
MAIN_OBJ = $(BUILD)/src/main.o
TEST_SRC = $(wildcard tests/check_*.c)
TEST_OBJ = $(TEST_SRC:%.c=$(BUILD)/%.o) $(patsubst %.c,$(BUILD)/%.o,$(wildcard tests/support/*.c))
WRAP     = -Wl,--wrap=malloc -Wl,--wrap=calloc -Wl,--wrap=realloc
# The embedder's library in two parts, one split used twice: the methods,
# and the derivative part (particles, forces, flow fields, the scenes and
# the util modules they use), which the plugin host is built from alone.
ENGINE_METHODS = $(addprefix src/engine/,adaptive.c dop853.c dop853_lc.c explicit.c implicit.c implicit_wide.c \
                 integrators.c lecture.c mistakes.c regularise.c rk45.c rkn.c rkn12.c rosenbrock.c rosenbrock_wide.c \
                 vern.c)
# The methods' lecture forms, for reading and for the tests: in the tool's
# archive only, neither the embedder's library nor the plugin host.
ENGINE_READING = src/engine/reference.c src/engine/reference_adaptive.c src/engine/reference_implicit.c
DERIV_SRC = $(filter-out $(ENGINE_METHODS) $(ENGINE_READING),$(wildcard src/engine/*.c)) $(wildcard src/scenes/*.c) \
            src/util/kv.c src/util/names.c src/util/num.c src/util/version.c
CORE_SRC = $(DERIV_SRC) $(ENGINE_METHODS) $(wildcard src/sim/*.c)
CORE_OBJ = $(CORE_SRC:%.c=$(BUILD)/%.o)
TOOLLIB  = $(BUILD)/libstepwise-tool.a
LIB      = $(BUILD)/libstepwise.a
BIN      = stepwise
TESTBIN  = $(BUILD)/check_stepwise
BENCHBIN = $(BUILD)/bench_engine
HOST     = $(BUILD)/stepwise-plugin-host

.PHONY: all deps run test test-full unit e2e layers sanitize bench clean install uninstall plugin-example fuzz

all: $(BIN) $(LIB) $(HOST)

deps:
	@sh tests/deps.sh

$(BUILD)/%.o: %.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) $(if $(filter src/tui/%,$<),$(CURSES_CFLAGS)) \
	    $(if $(filter tests/%,$<),$(CHECK_CFLAGS) -I$(BUILD)/tests -Itests/support) -c $< -o $@

$(TOOLLIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(LIB): $(CORE_OBJ)
	@rm -f $@ $(BUILD)/stepwise-core.o
	$(CC) -nostdlib -r -o $(BUILD)/stepwise-core.o $(CORE_OBJ)
	objcopy --wildcard --keep-global-symbol='sw_*' $(BUILD)/stepwise-core.o
	ar rcs $@ $(BUILD)/stepwise-core.o

# the plugin host beside it: `make stepwise` gives a binary that can run plugins
$(BIN): $(MAIN_OBJ) $(TUI_OBJ) $(TOOLLIB) | $(HOST)
	$(CC) $(OPT) $(LDSAN) -pthread -o $@ $(MAIN_OBJ) $(TUI_OBJ) $(TOOLLIB) $(CURSES_LIBS) $(SECCOMP_LIBS) -lm -ldl

# Each tests/check_NAME.c exports make_NAME_suite(); the list is generated so
# adding a suite never means editing the runner.
$(BUILD)/tests/suites.h: $(TEST_SRC)
	@mkdir -p $(dir $@)
	@for f in $(filter-out tests/check_main.c,$(TEST_SRC)); do \
	    n=$$(basename $$f .c); echo "SW_SUITE(make_$${n#check_}_suite)"; done > $@

$(BUILD)/tests/check_main.o: $(BUILD)/tests/suites.h

$(TESTBIN): $(TEST_OBJ) $(TOOLLIB)
	$(CC) $(OPT) $(LDSAN) $(WRAP) -pthread -o $@ $(TEST_OBJ) $(TOOLLIB) $(CHECK_LIBS) $(SECCOMP_LIBS) -lm -ldl

# A student plugin's host (docs/sandbox.md): the plugin interface, the
# engine's derivatives and the scenes' builders, and nothing of the methods
# (no method table, no built-in or fused step: the scenes are compiled with
# -DSW_FIELD_ONLY), so a plugin has no answer in its memory to call. Always
# built plain (no sanitizer: it defines malloc to see a step allocate), and
# found beside the program, in build/ beside it, or in LIBEXECDIR.
HOST_SRC = $(HOST_MAIN) $(DERIV_SRC) src/plugin/jail_filter.c
HOST_OBJ = $(HOST_SRC:%.c=$(BUILD)/host-obj/%.o)
$(BUILD)/host-obj/%.o: %.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -DSW_FIELD_ONLY -std=c11 -O2 -g $(VECT) $(MATH) $(WARN) $(CFLAGS) -MMD -MP -c $< -o $@
$(HOST): $(HOST_OBJ)
	$(CC) -O2 -g -o $@ $(HOST_OBJ) $(SECCOMP_LIBS) -lm -ldl

run: $(BIN) $(HOST)
	./$(BIN) lesson --next

unit: $(TESTBIN) $(HOST)
	$(CK_ENV) $(TESTBIN)

e2e: $(BIN) $(BENCHBIN) $(HOST)
	@STEPWISE_BENCH=$(BENCHBIN) sh tests/e2e/run.sh ./$(BIN)

# Includes point down the layers and no modules use each other in a circle
# (docs/architecture.md; the circles are read from the objects); the check
# proves it can fail before it runs on the tree.
layers: $(MAIN_OBJ) $(TUI_OBJ) $(LIB_OBJ)
	@sh tests/layers.sh --self-test
	@sh tests/layers.sh --objects $(BUILD)

# Two tiers of one suite. `make test` (the README's command) runs every
# behaviour at the quick tier: SW_TEST_QUICK=1 makes the minute-long sweeps
# (stability bisections, the full order tables, the slow claims) small or
# leaves them out, each case saying which. `make test-full` runs them whole;
# CI runs both (.ci/run).
# Check's per-case timeouts guard against a hang, never measure: scaled
# tenfold (CK_TIMEOUT_MULTIPLIER), so that a loaded machine is no hang.
TIER_ENV = SW_TEST_QUICK=1
CK_ENV   = CK_TIMEOUT_MULTIPLIER=$${CK_TIMEOUT_MULTIPLIER:-10}
# The unit and end-to-end suites run side by side, the end-to-end tests one
# more than the cores at a time (SW_TEST_JOBS=N: another number).
test: layers $(BIN) $(TESTBIN) $(BENCHBIN) $(HOST)
	@$(CK_ENV) $(TIER_ENV) STEPWISE_BENCH=$(BENCHBIN) sh tests/run_suite.sh $(TESTBIN) ./$(BIN)

test-full:
	@$(MAKE) --no-print-directory TIER_ENV='env -u SW_TEST_QUICK' test

# The sanitizer pass, at the quick tier; SW_SANITIZED leaves out what ASan
# itself makes impossible (its SIGSEGV handler, its address space).
sanitize:
	SW_SANITIZED=1 $(MAKE) BUILD=build/san SAN=1 BIN=build/san/stepwise test

# libFuzzer targets (clang): the lesson parser, the trace reader, the
# --set / number parsers, the canvas, the lesson runner, the check path, the
# roster reader and matcher, and source similarity. New inputs go to
# build/fuzz/corpus-NAME; crashes to build/fuzz/NAME-crash-*: copy one into
# tests/fuzz/NAME/ to keep it as a regression test (the unit suite replays
# that directory).
FUZZ_TIME ?= 60
FUZZERS   = lesson trace parse canvas runner check channel roster similar gradebook
FUZZ_FLAGS = -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -Iinclude -Isrc -Itests/support
fuzz:
	$(MAKE) CC=clang BUILD=build/fuzz FUZZ=1 build/fuzz/libstepwise-tool.a
	@for t in $(FUZZERS); do \
	    clang $(FUZZ_FLAGS) tests/fuzz/fuzz_$$t.c tests/support/fuzz_targets.c build/fuzz/libstepwise-tool.a \
	        $(SECCOMP_LIBS) -lm -ldl -o build/fuzz/fuzz_$$t || exit 1; \
	    mkdir -p build/fuzz/corpus-$$t; \
	    echo "fuzz: $$t for $(FUZZ_TIME) s"; \
	    build/fuzz/fuzz_$$t -max_total_time=$(FUZZ_TIME) -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
	        -artifact_prefix=build/fuzz/$$t- build/fuzz/corpus-$$t tests/fuzz/$$t 2>build/fuzz/$$t.log \
	        || { tail -40 build/fuzz/$$t.log; exit 1; }; \
	    grep -E "stat::number_of_executed_units" build/fuzz/$$t.log; \
	done

# The engine benchmark as its own program, linked with malloc/calloc/realloc
# wrapped so it can count every allocation our code makes in a step loop.
# Its peer comparison runs GSL's odeiv2 beside stepwise when GSL's
# development files are present: `make bench` installs them (bench/deps.sh);
# nothing else does, and the program and its library never link GSL. The
# stamp rebuilds the benchmark when GSL appears or goes.
GSL_FLAGS = $(shell pkg-config --exists gsl 2>/dev/null && echo -DSW_HAVE_GSL $$(pkg-config --cflags gsl))
GSL_LIBS  = $(shell pkg-config --exists gsl 2>/dev/null && pkg-config --libs gsl)
# The stiff comparison runs CVODE's BDF beside rodas4 when SUNDIALS's
# development files are present (libsundials-dev, also from bench/deps.sh).
CVODE_FLAGS = $(shell test -f /usr/include/cvode/cvode.h && echo -DSW_HAVE_CVODE)
CVODE_LIBS  = $(if $(CVODE_FLAGS),-lsundials_cvode -lsundials_nvecserial -lsundials_sunlinsolband \
              -lsundials_sunlinsoldense -lsundials_sunmatrixband -lsundials_sunmatrixdense)
BENCH_SRC = bench/bench_engine.c bench/bench_base.c bench/bench_peer.c bench/bench_chain_ref.c bench/bench_tree.c bench/bench_water.c bench/bench_rkn.c bench/bench_stiff.c bench/bench_frame.c bench/bench_implicit.c bench/bench_lc.c bench/bench_keys.c

$(BUILD)/gsl.stamp: FORCE
	@mkdir -p $(dir $@)
	@echo '$(GSL_FLAGS) $(CVODE_FLAGS)' | cmp -s - $@ || echo '$(GSL_FLAGS) $(CVODE_FLAGS)' > $@

$(BENCHBIN): $(BENCH_SRC) bench/bench_common.h tests/support/alloc_count.c $(TOOLLIB) $(BUILD)/gsl.stamp
	$(CC) $(CPPFLAGS) -Itests/support -std=c11 $(OPT) $(VECT) $(MATH) $(WARN) $(CFLAGS) $(GSL_FLAGS) $(CVODE_FLAGS) \
	    $(BENCH_SRC) tests/support/alloc_count.c $(TOOLLIB) $(LDSAN) $(WRAP) $(GSL_LIBS) $(CVODE_LIBS) $(SECCOMP_LIBS) \
	    -lm -o $@

bench:
	@sh bench/deps.sh
	@$(MAKE) --no-print-directory $(BENCHBIN)
	./$(BENCHBIN)
	@if command -v valgrind >/dev/null 2>&1; then echo; echo "instructions per particle-step (callgrind):"; \
	    sh bench/instructions.sh ./$(BENCHBIN); else echo "instructions per particle-step: skipped (no valgrind)"; fi
	@$(MAKE) --no-print-directory $(BIN) $(HOST)
	@echo; echo "one honest plugin, measured, jailed and not (bench/plugin_cost.sh):"
	@bash bench/plugin_cost.sh ./$(BIN) 5
	@echo; echo "grading a class of 120, jailed and not (bench/grade_class.sh):"
	@sh bench/grade_class.sh ./$(BIN) 120 3
	@echo; echo "grading 100 passing traces, CPU time (bench/grade_traces.sh):"
	@sh bench/grade_traces.sh ./$(BIN) 100 5
	@echo; echo "the longest stall after each key at n = 1e5, in tmux (bench/keys_tmux.sh):"
	@bash bench/keys_tmux.sh ./$(BIN) 3 3

# The lessons directory is compiled in (SW_DATADIR, from PREFIX). Remember it
# in a stamp, so that `make && make install PREFIX=/opt/sw` rebuilds what uses
# it rather than installing a binary that looks for its lessons elsewhere.
$(BUILD)/datadir.stamp: FORCE
	@mkdir -p $(dir $@)
	@echo '$(DATADIR) $(LIBEXECDIR)' | cmp -s - $@ || echo '$(DATADIR) $(LIBEXECDIR)' > $@
$(BUILD)/src/cli/common.o $(BUILD)/src/cli/plugin_build.o $(BUILD)/src/plugin/plugin_registry.o: $(BUILD)/datadir.stamp
FORCE:

LESSON_FILES = $(wildcard lessons/*.lesson lessons/README.md)

# For embedders: the engine library, the public headers and a pkg-config
# file (`pkg-config --cflags --libs stepwise`). Static only: Libs names what
# the engine needs (libm), and nothing else: the library holds no sandbox.
LIBDIR   = $(PREFIX)/lib
VERSION  = $(shell sed -n 's/^\#define SW_VERSION "\(.*\)"/\1/p' include/stepwise/base.h)

install: $(BIN) $(LIB) $(HOST)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(LIBEXECDIR) $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(DATADIR)/lessons $(DESTDIR)$(PREFIX)/include/stepwise $(DESTDIR)$(LIBDIR)/pkgconfig
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/stepwise
	install -m 755 $(HOST) $(DESTDIR)$(LIBEXECDIR)/stepwise-plugin-host
	install -m 644 docs/stepwise.1 $(DESTDIR)$(PREFIX)/share/man/man1/stepwise.1
	$(if $(LESSON_FILES),install -m 644 $(LESSON_FILES) $(DESTDIR)$(DATADIR)/lessons/)
	install -m 644 include/stepwise/*.h $(DESTDIR)$(PREFIX)/include/stepwise/
	install -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libstepwise.a
	printf '%s\n' 'prefix=$(PREFIX)' 'includedir=$${prefix}/include' 'libdir=$(LIBDIR)' '' \
	    'Name: stepwise' 'Description: particle systems and numerical integrators, as stepwise teaches them' \
	    'Version: $(VERSION)' 'Cflags: -I$${includedir}' \
	    'Libs: -L$${libdir} -lstepwise -lm' \
	    > $(DESTDIR)$(LIBDIR)/pkgconfig/stepwise.pc

# A student's integrator as a shared object: examples/euler_plugin.c is the
# template (docs/plugins.md); load it with --plugin examples/euler_plugin.so.
plugin-example: examples/euler_plugin.so

# Built as a student would, with plain flags whatever the build (a sanitized
# plugin cannot be loaded by a plain stepwise; the reverse works).
examples/euler_plugin.so: examples/euler_plugin.c include/stepwise/integrator.h include/stepwise/ode.h
	$(CC) -std=c11 -O2 -g $(WARN) $(CFLAGS) -shared -fPIC -Iinclude -o $@ examples/euler_plugin.c

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/stepwise $(DESTDIR)$(PREFIX)/share/man/man1/stepwise.1
	rm -rf $(DESTDIR)$(DATADIR) $(DESTDIR)$(LIBEXECDIR) $(DESTDIR)$(PREFIX)/include/stepwise
	rm -f $(DESTDIR)$(LIBDIR)/libstepwise.a $(DESTDIR)$(LIBDIR)/pkgconfig/stepwise.pc

clean:
	rm -rf build $(BIN)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
