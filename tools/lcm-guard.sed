# tools/lcm-guard.sed — applied by the Makefile to every decoder lcm-gen
# writes (build/gen/vroc_*.c).  LCM 1.3's decoders trust a message's array
# counts: a count past the end of the message is allocated (sizeof * count,
# up to 2^31 elements) and, for arrays of numbers, checked against the bytes
# left with an int product that overflows, so one malformed message crashed
# a worker (make fuzz found it: tests/test_wire.c).  Each array's
# allocation is guarded: a count below 0 or beyond what the bytes left can
# hold refuses the message (the count set to 0 first, so that the cleanup
# frees only what was allocated), and arrays are zeroed (calloc) so that
# the cleanup of a message refused half-way frees nothing twice.
# An array of numbers: its elements are sizeof(T) bytes on the wire.
s/^( *)(p\[element\]\.[a-z0-9_]+ = \((int8_t|int16_t|int32_t|int64_t|float|double)\*\) lcm_malloc\(sizeof\(\3\) \* p\[element\]\.([a-z0-9_]+)\);)/\1if (p[element].\4 < 0 || p[element].\4 > (maxlen - pos) \/ (int)sizeof(\3)) { p[element].\4 = 0; return -1; }\n\1\2/
# An array of messages: each element takes at least one byte.
s/^( *)(p\[element\]\.[a-z0-9_]+ = \((vroc_[a-z0-9_]+)\*\) lcm_malloc\(sizeof\(\3\) \* p\[element\]\.([a-z0-9_]+)\);)/\1if (p[element].\4 < 0 || p[element].\4 > maxlen - pos) { p[element].\4 = 0; return -1; }\n\1\2/
s/(p\[element\]\.[a-z0-9_]+ = \([a-z0-9_]+\*\) )lcm_malloc\(/\1calloc(1, /
# Strings: lcm_coretypes.h's decoder allocates whatever length the message
# says (a negative one too) and does not check the closing NUL that the
# users' strlen relies on; vr_string_decode, put at the top of the file,
# refuses both before it is called.
1i\
#include <stdint.h>\
/* tools/lcm-guard.sed: a string's length must fit the bytes left and end in NUL */\
static inline __attribute__((unused)) int vr_string_fits(const void *buf, int offset, int maxlen)\
{\
    const unsigned char *b = (const unsigned char *)buf + offset;\
    int32_t len;\
    if (maxlen < 4) return 0;\
    len = (int32_t)(((uint32_t)b[0] << 24) | ((uint32_t)b[1] << 16) | ((uint32_t)b[2] << 8) | b[3]);\
    return len >= 1 && len <= maxlen - 4 && b[4 + len - 1] == 0;\
}
s/thislen = __string_decode_array\(buf, offset \+ pos, maxlen - pos, ([^;]*), 1\);/thislen = vr_string_fits(buf, offset + pos, maxlen - pos) ? __string_decode_array(buf, offset + pos, maxlen - pos, \1, 1) : -1;/
