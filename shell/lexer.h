/* lexer.h — the lexical rules of SPEC 1: lines, words, names, numbers,
 * vectors.  A Lexer walks one cleaned line; every scanner returns 0 and
 * advances, or returns -1 with a message in err and leaves the position
 * where the trouble is. */
#ifndef VROC_LEXER_H
#define VROC_LEXER_H

#include <stddef.h>

typedef struct Lexer {
    const char *p;       /* next character */
    const char *end;     /* the line's end (a NUL is there too) */
} Lexer;

/* Strips the line end (LF, CRLF), a `#` comment and surrounding blanks, in
 * place.  Refuses NUL bytes and control characters with a message.
 * On success (*text, *textlen) is what is left (possibly empty, NUL-terminated). */
int lx_clean(char *line, size_t len, char **text, size_t *textlen, char *err, size_t n);

void lx_init(Lexer *lx, const char *text, size_t len);
void lx_skip_blanks(Lexer *lx);
int lx_at_end(Lexer *lx);           /* after blanks */
int lx_accept(Lexer *lx, char c);   /* after blanks: consumes c when it is next */

/* the next "token" for messages and lookup: up to a blank or '=' */
size_t lx_token_len(const Lexer *lx);

/* a name [A-Za-z_][A-Za-z0-9_.-]*, at most VR_NAME_MAX bytes, copied into name */
int lx_name(Lexer *lx, const char *what, char *name, size_t size, char *err, size_t n);
/* a decimal number (strtod form, no hex, inf or nan) */
int lx_number(Lexer *lx, const char *what, double *v, char *err, size_t n);
/* "(a,b,c)" with count numbers, blanks allowed */
int lx_vector(Lexer *lx, const char *what, double *v, int count, char *err, size_t n);
/* an unsigned decimal integer up to 2^64-1 */
int lx_uint64(Lexer *lx, const char *what, unsigned long long *v, char *err, size_t n);
/* the rest of the line (trimmed; may be empty) */
void lx_rest(Lexer *lx, const char **s, size_t *len);
/* a run of non-blank characters */
void lx_word(Lexer *lx, const char **s, size_t *len);

/* 'text' for a message: quoted, control and non-ASCII bytes escaped,
 * shortened with "..." past about 40 characters (a 1 MB word stays short) */
void lx_quote(char *buf, size_t size, const char *s, size_t len);

/* did-you-mean: the candidate nearest to word (optimal string alignment
 * distance, case ignored), or NULL when none is close */
const char *lx_suggest(const char *word, size_t len, const char *const *cands, int ncands);

#endif
