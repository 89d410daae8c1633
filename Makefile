# VROC — a plain Makefile, no configure step.
#
#   make          libvroc.a, vroc, vroc-gp, vroc-render.so in this folder
#   make check    every test, built with ASan+UBSan (last line: N passed, M failed)
#   make demo     runs scenes/demo.cmd and writes its frames and a picture
#   make bench    prints the benchmarks (release build, bench/run.sh)
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
LIBS   = -lccd -lklu -llcm -ldl -lm
RL_LIBS = -lreadline
GL_LIBS = -lOSMesa

rel_OPT     = -O3 -g -fno-math-errno -flto=auto
rel_CFLAGS  = $(rel_OPT) -ffat-lto-objects
asan_CFLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
rel_LDFLAGS  = $(rel_OPT)
asan_LDFLAGS = -fsanitize=address,undefined

LIB_SRC    := $(filter-out src/render.c,$(wildcard src/*.c src/parallel/*.c))
LCM_TYPES  := $(wildcard src/parallel/*.lcm)
LCM_GEN    := $(patsubst src/parallel/%.lcm,build/gen/vroc_%.c,$(LCM_TYPES))
SHELL_SRC  := $(filter-out shell/gp_main.c,$(wildcard shell/*.c))
TEST_SRC   := $(wildcard tests/*.c)
BENCH_SRC  := $(wildcard bench/bench_*.c)

PRODUCTS = libvroc.a vroc vroc-gp vroc-render.so

.PHONY: all deps check check-asan demo bench install clean
.SECONDARY: $(LCM_GEN)
.DELETE_ON_ERROR:

all: $(PRODUCTS)

deps:
	@sh tools/install-deps.sh

build/deps.stamp: tools/install-deps.sh
	@sh tools/install-deps.sh
	@mkdir -p build && touch $@

$(PRODUCTS): %: build/rel/%
	cp $< $@

# LCM message types: C code generated at build time, never checked in.  The
# generated code is not -pedantic clean (function pointer <-> void *), so it
# is compiled with those two warnings off.
build/gen/vroc_%.c: src/parallel/%.lcm | build/deps.stamp
	@mkdir -p build/gen
	lcm-gen -c --c-cpath build/gen --c-hpath build/gen $<
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

build/$(1)/gen/%.o: build/gen/%.c | $$(LCM_GEN)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) -Wno-pedantic -Wno-format -Wno-unused-parameter $$(DEFS) -Ibuild/gen $$($(1)_CFLAGS) -MMD -MP -c $$< -o $$@

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

# one runner: tests/main.c and every tests/*.c beside it (each test_*.c a suite)
build/$(1)/tests/vroc-tests: $$(patsubst %.c,build/$(1)/%.o,$$(TEST_SRC)) build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

# a benchmark: one program each (bench/bench_*.c)
build/$(1)/bench/%: build/$(1)/bench/%.o build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

$(1)-all: build/$(1)/libvroc.a build/$(1)/vroc build/$(1)/vroc-gp build/$(1)/vroc-render.so $$($(1)_TESTS)
-include $$($(1)_OBJ:.o=.d) $$(patsubst %.c,build/$(1)/%.d,$$(SHELL_SRC) $$(TEST_SRC) $$(BENCH_SRC) shell/gp_main.c)
endef
$(foreach v,rel asan,$(eval $(call VARIANT,$(v))))

check: check-asan

check-asan: asan-all $(PRODUCTS)
	@sh tests/run.sh build/asan

bench: rel-all $(rel_BENCH)
	@sh bench/run.sh build/rel

demo: all
	@sh tools/demo.sh

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/vroc $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 vroc vroc-gp $(DESTDIR)$(PREFIX)/bin/
	install -m 644 vroc-render.so $(DESTDIR)$(PREFIX)/lib/vroc/
	install -m 644 man/vroc.1 man/vroc-gp.1 $(DESTDIR)$(PREFIX)/share/man/man1/

clean:
	rm -rf build $(PRODUCTS)
