# VROC — a plain Makefile, no configure step.
#
#   make          libvroc.a, vroc, vroc-gp, vroc-render.so in this folder
#   make check    every test, built with ASan+UBSan (last line: N passed, M failed)
#   make demo     runs scenes/demo.cmd and writes its frames and a picture
#   make bench    prints the benchmarks (release build)
#   make deps     installs the Debian packages when missing
#   make install  under PREFIX (bin/, lib/vroc/, share/man/man1/)
#
# Two variants share the rules below: build/rel (-O3, and no errno from
# math functions: sqrt becomes one instruction; nothing reads errno after
# one) and build/asan (-fsanitize=address,undefined).  The results are the
# same bits as at -O2 (no fast-math: IEEE semantics kept); the peers'
# 100-object scene takes 6.6 % fewer instructions and about 10 % less time.
# build/rel also links with link-time optimisation, which inlines the small
# functions one file calls in another (a body's pose, the walk's entry, the
# distance bounds): the same bits again, 3 % fewer instructions and 3-10 %
# more frames/s in that scene.  Its objects are fat (real code beside the
# LTO code), so libvroc.a links into a program built without -flto too.
# Sources are found by wildcard, so a new file in src/, shell/ or tests/
# needs no edit here.

PREFIX ?= /usr/local

WARN   = -std=c99 -Wall -Wextra -pedantic -Werror
DEFS   = -D_POSIX_C_SOURCE=200809L
INCS   = -Iinclude -Isrc -isystem /usr/include/suitesparse
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
TEST_SRC   := $(wildcard tests/test_*.c)
BENCH_SRC  := $(wildcard tests/bench_*.c)
# the other .c files in tests/ are helpers linked into every test binary
TEST_HELP_SRC := $(filter-out $(TEST_SRC) $(BENCH_SRC),$(wildcard tests/*.c))

PRODUCTS = libvroc.a vroc vroc-gp vroc-render.so

.PHONY: all deps check check-asan demo bench install clean
.SECONDARY: $(LCM_GEN)
.DELETE_ON_ERROR:

all: $(PRODUCTS)

deps:
	@sh tools/install-deps.sh

$(PRODUCTS): %: build/rel/%
	cp $< $@

# LCM message types: C code generated at build time, never checked in.  The
# generated code is not -pedantic clean (function pointer <-> void *), so it
# is compiled with those two warnings off.
build/gen/vroc_%.c: src/parallel/%.lcm | deps
	@mkdir -p build/gen
	lcm-gen -c --c-cpath build/gen --c-hpath build/gen $<
# the header comes with the .c: a type's other users (its .d files name the
# header) are rebuilt after it changes, not compiled against the old one
build/gen/vroc_%.h: build/gen/vroc_%.c ;

define VARIANT
$(1)_OBJ := $$(patsubst %.c,build/$(1)/%.o,$$(LIB_SRC)) \
            $$(patsubst build/gen/%.c,build/$(1)/gen/%.o,$$(LCM_GEN))
$(1)_TESTS := $$(patsubst tests/%.c,build/$(1)/tests/%,$$(TEST_SRC))
$(1)_BENCH := $$(patsubst tests/%.c,build/$(1)/tests/%,$$(BENCH_SRC))
$(1)_TEST_HELP := $$(patsubst %.c,build/$(1)/%.o,$$(TEST_HELP_SRC))
# kept, so that make check's last line is its summary, not make's clean-up
.SECONDARY: $$(patsubst %.c,build/$(1)/%.o,$$(TEST_SRC) $$(BENCH_SRC) $$(TEST_HELP_SRC))

build/$(1)/%.o: %.c | $$(LCM_GEN) deps
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$(INCS) -Ibuild/gen $$($(1)_CFLAGS) -MMD -MP -c $$< -o $$@

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
build/$(1)/vroc-render.so: src/render.c src/render.h | deps
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(DEFS) $$(INCS) $$($(1)_CFLAGS) -fPIC -shared -o $$@ $$< $$($(1)_LDFLAGS) $$(GL_LIBS) -lm

build/$(1)/tests/%: build/$(1)/tests/%.o $$($(1)_TEST_HELP) build/$(1)/libvroc.a
	$$(CC) $$($(1)_LDFLAGS) -o $$@ $$^ $$(LIBS)

$(1)-all: build/$(1)/libvroc.a build/$(1)/vroc build/$(1)/vroc-gp build/$(1)/vroc-render.so $$($(1)_TESTS)
-include $$($(1)_OBJ:.o=.d) $$(patsubst %.c,build/$(1)/%.d,$$(SHELL_SRC) $$(TEST_SRC) $$(BENCH_SRC) $$(TEST_HELP_SRC) shell/gp_main.c)
endef
$(foreach v,rel asan,$(eval $(call VARIANT,$(v))))

check: check-asan

check-asan: asan-all $(PRODUCTS)
	@sh tests/run.sh build/asan

bench: rel-all $(rel_BENCH)
	@sh tools/bench.sh build/rel

demo: all
	@sh tools/demo.sh

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/vroc $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 vroc vroc-gp $(DESTDIR)$(PREFIX)/bin/
	install -m 644 vroc-render.so $(DESTDIR)$(PREFIX)/lib/vroc/
	install -m 644 man/vroc.1 $(DESTDIR)$(PREFIX)/share/man/man1/

clean:
	rm -rf build $(PRODUCTS)
