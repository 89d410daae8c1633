# VROC — a plain Makefile, no configure step.
#
#   make          libvroc.a, vroc, vroc-gp, vroc-render.so, vroc-window.so in this folder, and
#                 tools/vroc-sound (a sound log to WAV: libsndfile) and
#                 tools/vroc-tracker (a track file published over LCM)
#   make check    every test, built with ASan+UBSan (last line: N passed, M failed)
#   make demo     runs scenes/demo.cmd and writes its frames and a picture
#   make bench    prints the benchmarks (release build, bench/run.sh; installs ODE
#                 for bench_ode, the peers' rooms run in ODE beside vroc)
#   make fuzz     AFL++ for FUZZ_S seconds (last line: fuzz: N execs, M crashes, K hangs)
#   make valgrind memcheck on every feature but the drawing (also in make check)
#   make lint     cppcheck, clang-tidy (.clang-tidy), gcc -fanalyzer (last line: lint: N findings ...)
#   make deps     installs the Debian packages when missing
#   make install  under PREFIX (bin/, lib/vroc/, share/man/man1/)
#
# Two variants share the rules below: build/rel (-O3, and no errno from
# math functions: sqrt becomes one instruction; nothing reads errno after
# one) and build/asan (-fsanitize=address,undefined).  The results are the
# same bits as at -O2 (no fast-math: IEEE semantics kept).  build/rel also
# links with link-time optimisation, which inlines the small functions one
# file calls in another (a body's pose, the walk's entry, the distance
# bounds): the same bits again.  Its objects are fat (real code beside the
# LTO code), so libvroc.a links into a program built without -flto too.
# Sources are found by wildcard, so a new file in src/, shell/, tests/ or
# bench/ needs no edit here: every tests/*.c goes into the one test runner,
# build/VARIANT/tests/vroc-tests; each bench/bench_*.c is a program of its own.
# The shell sees include/ only (it uses vroc.h, never the library's
# insides); the library and the tests see src/ too.
# `make deps` checks for the Debian packages every time it is asked; the
# builds depend on a stamp that reruns that check when install-deps.sh
# changes (a new dependency), so an ordinary build does not.

PREFIX ?= /usr/local

WARN   = -std=c99 -Wall -Wextra -pedantic -Werror
DEFS   = -D_POSIX_C_SOURCE=200809L
INCS   = -Iinclude -Isrc -Ibuild/gen -isystem /usr/include/suitesparse
SHELL_INCS = -Iinclude
LIBS   = -lccd -lklu -llcm -lpng -ldl -lm
RL_LIBS = -lreadline
GL_LIBS = -lOSMesa
SND_LIBS = -lsndfile
WIN_LIBS = -lglfw -lGL
X_LIBS = -lX11

rel_OPT     = -O3 -g -fno-math-errno -flto=auto
rel_CFLAGS  = $(rel_OPT) -ffat-lto-objects
asan_CFLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
rel_LDFLAGS  = $(rel_OPT)
asan_LDFLAGS = -fsanitize=address,undefined
# build/fuzz: the library and shell compiled by afl-clang-fast for `make fuzz`
# (AFL++'s coverage instrumentation; no sanitizers: a crash AFL++ finds is
# replayed under build/asan, where it becomes a test)
fuzz_CFLAGS  = -O2 -g
fuzz_LDFLAGS =

LIB_SRC    := $(filter-out src/render.c src/window_glfw.c,$(wildcard src/*.c src/parallel/*.c))
LCM_TYPES  := $(wildcard src/parallel/*.lcm)
LCM_GEN    := $(patsubst src/parallel/%.lcm,build/gen/vroc_%.c,$(LCM_TYPES))
SHELL_SRC  := $(filter-out shell/gp_main.c,$(wildcard shell/*.c))
TEST_SRC   := $(wildcard tests/*.c)
BENCH_SRC  := $(wildcard bench/bench_*.c)

PRODUCTS = libvroc.a vroc vroc-gp vroc-render.so vroc-window.so
# C programs of tools/ (tools/src/NAME.c), built beside the others and
# copied to tools/NAME
TOOLS = vroc-sound vroc-tracker

.PHONY: all deps check check-asan demo bench install clean fuzz valgrind lint
.SECONDARY: $(LCM_GEN)
.DELETE_ON_ERROR:

all: $(PRODUCTS) $(patsubst %,tools/%,$(TOOLS))

deps:
	@sh tools/install-deps.sh

build/deps.stamp: tools/install-deps.sh
	@sh tools/install-deps.sh
	@mkdir -p build && touch $@

$(PRODUCTS): %: build/rel/%
	cp $< $@

tools/%: build/rel/%
	cp $< $@

# LCM message types: C code generated at build time, never checked in.  The
# generated code is not -pedantic clean (function pointer <-> void *), so it
# is compiled with those two warnings off.
# Each decoder is patched by tools/lcm-guard.sed: LCM 1.3's trust a
# message's array counts (see there); the grep makes sure none is missed.
build/gen/vroc_%.c: src/parallel/%.lcm tools/lcm-guard.sed | build/deps.stamp
	@mkdir -p build/gen
	lcm-gen -c --c-cpath build/gen --c-hpath build/gen $<
	sed -E -i -f tools/lcm-guard.sed $@
	@! grep -n 'p\[element\]\.[a-z0-9_]* = .*lcm_malloc' $@ || { echo "$@: an array tools/lcm-guard.sed missed" >&2; exit 1; }
# the header comes with the .c: a type's other users (its .d files name the
# header) are rebuilt after it changes, not compiled against the old one
build/gen/vroc_%.h: build/gen/vroc_%.c ;

define VARIANT
$(1)_OBJ := $$(patsubst %.c,build/$(1)/%.o,$$(LIB_SRC)) \
            $$(patsubst build/gen/%.c,build/$(1)/gen/%.o,$$(LCM_GEN))
$(1)_TESTS := build/$(1)/tests/vroc-tests
$(1)_BENCH := $$(patsubst bench/%.c,build/$(1)/bench/%,$$(BENCH_SRC))
# kept, so that make check's last line is its summary, not make's clean-up
.SECONDARY: $$(patsubst %.c,build/$(1)/%.o,$$(TEST_SRC) $$(BENCH_SRC))

build/$(1)/%.o: %.c | $$(LCM_GEN) build/deps.stamp
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$(INCS) $$($(1)_CFLAGS) -MMD -MP -c $$< -o $$@

build/$(1)/shell/%.o: INCS = $$(SHELL_INCS)

# -fno-strict-aliasing: LCM's coretypes decode a double through an int64_t
# pointer; with the message zeroed first (link.h's VR_HANDLER), -O3 with
# link-time optimisation kept the zeros and the release build's in-process
# workers stopped answering (a pile with gps = 2, lcm_url = memq://)
build/$(1)/gen/%.o: build/gen/%.c | $$(LCM_GEN)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -Wno-pedantic -Wno-format -Wno-unused-parameter -fno-strict-aliasing $$(DEFS) -Ibuild/gen $$($(1)_CFLAGS) -MMD -MP -c $$< -o $$@

build/$(1)/libvroc.a: $$($(1)_OBJ)
	rm -f $$@
	ar rcs $$@ $$^

build/$(1)/vroc: $$(patsubst %.c,build/$(1)/%.o,$$(SHELL_SRC)) build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(RL_LIBS) $$(LIBS)

build/$(1)/vroc-gp: build/$(1)/shell/gp_main.o build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

# the renderer is a module of its own, dlopen()ed on first use, so that a
# run without a display never loads OSMesa (and the LLVM it pulls in)
build/$(1)/vroc-render.so: src/render.c src/render.h | build/deps.stamp
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$(INCS) $$($(1)_CFLAGS) -fPIC -shared -o $$@ $$< $$($(1)_LDFLAGS) $$(GL_LIBS) -lm

# tools/vroc-sound: a sound log rendered to a WAV (SPEC 8)
build/$(1)/vroc-sound: build/$(1)/tools/src/vroc-sound.o
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(SND_LIBS) -lm

# tools/vroc-tracker: a track file published in real time (SPEC 8)
build/$(1)/vroc-tracker: build/$(1)/tools/src/vroc-tracker.o build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

# the window is a module too: X, GL and GLFW load only when `window` opens it
build/$(1)/vroc-window.so: src/window_glfw.c src/window_module.h src/render.h include/vroc.h | build/deps.stamp
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$(INCS) $$($(1)_CFLAGS) -fPIC -shared -o $$@ $$< $$($(1)_LDFLAGS) $$(WIN_LIBS)

# the window tests' screenshot (tests/window.sh): one X window's pixels as a PPM
build/$(1)/tests/xshot: tests/x11/xshot.c | build/deps.stamp
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$($(1)_CFLAGS) -o $$@ $$< $$($(1)_LDFLAGS) $$(X_LIBS)

# one runner: tests/main.c and every tests/*.c beside it (each test_*.c a suite)
build/$(1)/tests/vroc-tests: $$(patsubst %.c,build/$(1)/%.o,$$(TEST_SRC)) build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

# a benchmark: one program each (bench/bench_*.c)
build/$(1)/bench/%: build/$(1)/bench/%.o build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

$(1)-all: build/$(1)/libvroc.a build/$(1)/vroc build/$(1)/vroc-gp build/$(1)/vroc-render.so build/$(1)/vroc-window.so \
          build/$(1)/tests/xshot $$($(1)_TESTS) $$(patsubst %,build/$(1)/%,$$(TOOLS))
-include $$($(1)_OBJ:.o=.d) $$(patsubst %.c,build/$(1)/%.d,$$(SHELL_SRC) $$(TEST_SRC) $$(BENCH_SRC) shell/gp_main.c) \
         $$(patsubst %,build/$(1)/tools/src/%.d,$$(TOOLS))
endef
$(foreach v,rel asan fuzz,$(eval $(call VARIANT,$(v))))

# ---- make fuzz (SPEC 11): AFL++ on the command parser, the OFF reader and
# LCM message decoding.  Harnesses in tools/fuzz/ (not tests/: every
# tests/*.c is linked into the test runner).  FUZZ_S seconds in all, shared
# by the targets; FUZZ_TARGETS picks some.  Writes only under build/fuzz/.
FUZZ_S ?= 60
FUZZ_TARGETS ?= shell off lcm
FUZZ_BIN := $(patsubst %,build/fuzz/fuzz-%,shell off lcm) build/fuzz/lcm-seeds
build/fuzz/%: CC = afl-clang-fast
build/fuzz/%: export AFL_QUIET = 1
# AFL++'s persistent-mode macros are not ISO C (statement expressions)
build/fuzz/tools/fuzz/%.o: WARN += -Wno-pedantic -Wno-gnu-statement-expression
build/fuzz/tools/fuzz/%.o: INCS += -Ishell -Isrc/parallel
build/fuzz.stamp: tools/install-deps.sh
	@sh tools/install-deps.sh fuzz
	@mkdir -p build && touch $@
# every object afl-clang-fast compiles waits for it to be installed (an
# order-only prerequisite of a pattern without a recipe would be a rule of
# its own, not one added to build/fuzz/%.o's: a fresh machine's -j2 build
# then ran afl-clang-fast before the stamp had installed it)
$(fuzz_OBJ) $(patsubst %.c,build/fuzz/%.o,$(SHELL_SRC) $(wildcard tools/fuzz/*.c)): | build/fuzz.stamp

build/fuzz/fuzz-shell: build/fuzz/tools/fuzz/fuzz_shell.o $(patsubst %.c,build/fuzz/%.o,$(filter-out shell/main.c,$(SHELL_SRC))) build/fuzz/libvroc.a
	$(CC) -o $@ $^ $(RL_LIBS) $(LIBS)
build/fuzz/fuzz-off build/fuzz/fuzz-lcm: build/fuzz/fuzz-%: build/fuzz/tools/fuzz/fuzz_%.o build/fuzz/libvroc.a
	$(CC) -o $@ $^ $(LIBS)
build/fuzz/lcm-seeds: build/fuzz/tools/fuzz/lcm_seeds.o build/fuzz/libvroc.a
	$(CC) -o $@ $^ $(LIBS)

fuzz: $(FUZZ_BIN)
	@sh tools/fuzz/afl.sh "$(FUZZ_S)" $(FUZZ_TARGETS)

# ---- make valgrind (SPEC 11): memcheck on the release build, every feature
# but the drawing; about 2 minutes on 2 shared cores, so make check runs it
# too (tests/valgrind.sh is one of its suites) and it cannot rot.
valgrind: rel-all
	@sh tests/valgrind.sh

# ---- make lint: cppcheck, clang-tidy (its checks and the reasons for them
# in .clang-tidy) and gcc -fanalyzer, over src/, shell/ and tools/fuzz/
# (tools/lint.sh); false positives are silenced inline, with the reason.
build/lint.stamp: tools/install-deps.sh
	@sh tools/install-deps.sh lint
	@mkdir -p build && touch $@
lint: $(LCM_GEN) build/lint.stamp
	@sh tools/lint.sh

check: check-asan

check-asan: asan-all $(PRODUCTS)
	@sh tests/run.sh build/asan

bench: rel-all $(rel_BENCH)
	@sh bench/run.sh build/rel

# bench_ode (issue 26): the peers' rooms in ODE beside vroc, in one process.
# Only it links -lode and only its object waits for ODE's headers (installed
# by `install-deps.sh bench`, explicit targets for the reason given at
# build/fuzz.stamp), so the rest of the build, `make` and `make check`, needs
# no ODE.
ODE_BENCH := $(foreach v,rel asan,build/$(v)/bench/bench_ode)
$(ODE_BENCH): LIBS += -lode
$(ODE_BENCH:=.o): | build/bench.stamp
build/bench.stamp: tools/install-deps.sh
	@sh tools/install-deps.sh bench
	@mkdir -p build && touch $@

demo: all
	@sh tools/demo.sh

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/vroc $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 vroc vroc-gp $(patsubst %,tools/%,$(TOOLS)) $(DESTDIR)$(PREFIX)/bin/
	install -m 644 vroc-render.so vroc-window.so $(DESTDIR)$(PREFIX)/lib/vroc/
	install -m 644 man/vroc.1 man/vroc-gp.1 $(DESTDIR)$(PREFIX)/share/man/man1/

clean:
	rm -rf build $(PRODUCTS) $(patsubst %,tools/%,$(TOOLS))
