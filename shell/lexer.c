/* lexer.c — SPEC 1's lexical rules.  Lines are whatever length getline
 * gave; nothing here copies a line or assumes a bound on it. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lexer.h"
#include "vroc.h"

static int is_blank(char c) { return c == ' ' || c == '\t'; }
static int is_digit(char c) { return c >= '0' && c <= '9'; }
static int is_name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
static int is_name_char(char c) { return is_name_start(c) || is_digit(c) || c == '.' || c == '-'; }
static int is_control(unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7f; }

int lx_clean(char *line, size_t len, char **text, size_t *textlen, char *err, size_t n)
{
    char *hash, *s = line, *e;
    size_t i;
    if (len > 0 && line[len - 1] == '\n') len--;
    if (len > 0 && line[len - 1] == '\r') len--;   /* CRLF */
    if (memchr(line, '\0', len)) {
        snprintf(err, n, "line contains a NUL byte (at column %d); not a text line",
                 (int)((char *)memchr(line, '\0', len) - line) + 1);
        return -1;
    }
    line[len] = '\0';
    hash = memchr(line, '#', len);                 /* a comment runs to the line end */
    if (hash) {
        *hash = '\0';
        len = (size_t)(hash - line);
    }
    for (i = 0; i < len; i++)
        if (is_control((unsigned char)line[i])) {
            snprintf(err, n, "line contains the control character \\x%02x (at column %lu); not a text line",
                     (unsigned char)line[i], (unsigned long)i + 1);
            return -1;
        }
    e = line + len;
    while (s < e && is_blank(*s)) s++;
    while (e > s && is_blank(e[-1])) e--;
    *e = '\0';
    *text = s;
    *textlen = (size_t)(e - s);
    return 0;
}

void lx_init(Lexer *lx, const char *text, size_t len)
{
    lx->p = text;
    lx->end = text + len;
}

void lx_skip_blanks(Lexer *lx)
{
    while (lx->p < lx->end && is_blank(*lx->p)) lx->p++;
}

int lx_at_end(Lexer *lx)
{
    lx_skip_blanks(lx);
    return lx->p == lx->end;
}

int lx_accept(Lexer *lx, char c)
{
    lx_skip_blanks(lx);
    if (lx->p < lx->end && *lx->p == c) {
        lx->p++;
        return 1;
    }
    return 0;
}

size_t lx_token_len(const Lexer *lx)
{
    const char *q = lx->p;
    while (q < lx->end && !is_blank(*q) && *q != '=') q++;
    if (q == lx->p && q < lx->end) q++;   /* a lone '=' is a token too */
    return (size_t)(q - lx->p);
}

void lx_quote(char *buf, size_t size, const char *s, size_t len)
{
    size_t o = 0, i;
    const size_t shown = 40;
    if (size < 16) {
        if (size) buf[0] = '\0';
        return;
    }
    buf[o++] = '\'';
    for (i = 0; i < len && i < shown && o + 8 < size; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x20 || c >= 0x7f) o += (size_t)snprintf(buf + o, size - o, "\\x%02x", c);
        else buf[o++] = (char)c;
    }
    if (i < len && o + 5 < size) {
        memcpy(buf + o, "...", 3);
        o += 3;
    }
    buf[o++] = '\'';
    buf[o] = '\0';
}

/* "got 'x'" or "got nothing": what a scanner found instead of a number or
 * vector (up to a blank, '=', or the ',' or ')' that ends a number) */
static void got(const Lexer *lx, char *buf, size_t size)
{
    char q[64];
    const char *e = lx->p;
    if (lx->p == lx->end) {
        snprintf(buf, size, "got nothing");
        return;
    }
    while (e < lx->end && !is_blank(*e) && *e != '=' && (e == lx->p || (*e != ',' && *e != ')'))) e++;
    lx_quote(q, sizeof q, lx->p, (size_t)(e - lx->p));
    snprintf(buf, size, "got %s", q);
}

int lx_name(Lexer *lx, const char *what, char *name, size_t size, char *err, size_t n)
{
    const char *s, *q;
    char g[80];
    size_t len;
    lx_skip_blanks(lx);
    s = q = lx->p;
    if (q == lx->end) {
        snprintf(err, n, "'%s' needs a name", what);
        return -1;
    }
    while (q < lx->end && is_name_char(*q)) q++;
    len = (size_t)(q - s);
    if (!is_name_start(*s) || (q < lx->end && !is_blank(*q))) {
        lx_quote(g, sizeof g, s, lx_token_len(lx));
        snprintf(err, n, "bad name %s for '%s' (a letter or _, then letters, digits, _ . -)", g, what);
        return -1;
    }
    if (len > VR_NAME_MAX || len >= size) {
        lx_quote(g, sizeof g, s, len);
        snprintf(err, n, "name %s is too long (%lu bytes, at most %d)", g, (unsigned long)len, VR_NAME_MAX);
        return -1;
    }
    memcpy(name, s, len);
    name[len] = '\0';
    lx->p = q;
    return 0;
}

/* the strtod decimal forms, without hex, inf and nan; NULL if none */
static const char *scan_decimal(const char *p)
{
    int digits = 0;
    if (*p == '+' || *p == '-') p++;
    while (is_digit(*p)) p++, digits++;
    if (*p == '.') {
        p++;
        while (is_digit(*p)) p++, digits++;
    }
    if (!digits) return NULL;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        if (*q == '+' || *q == '-') q++;
        if (is_digit(*q)) {
            while (is_digit(*q)) q++;
            p = q;
        }
    }
    return p;
}

static int ends_number(const Lexer *lx, const char *q)
{
    return q == lx->end || is_blank(*q) || *q == ',' || *q == ')';
}

int lx_number(Lexer *lx, const char *what, double *v, char *err, size_t n)
{
    const char *q;
    char *e;
    char g[80];
    lx_skip_blanks(lx);
    q = lx->p < lx->end ? scan_decimal(lx->p) : NULL;
    if (!q || !ends_number(lx, q)) {
        got(lx, g, sizeof g);
        snprintf(err, n, "'%s' needs a number, %s", what, g);
        return -1;
    }
    errno = 0;
    *v = strtod(lx->p, &e);
    if (e != q || isinf(*v) || isnan(*v)) {
        lx_quote(g, sizeof g, lx->p, (size_t)(q - lx->p));
        snprintf(err, n, "number %s for '%s' is too large (beyond 1.8e308)", g, what);
        return -1;
    }
    if (errno == ERANGE && fabs(*v) < DBL_MIN) {   /* no silent zero (SPEC 11) */
        lx_quote(g, sizeof g, lx->p, (size_t)(q - lx->p));
        snprintf(err, n, "number %s for '%s' is too small (below 2.2e-308; write 0 for zero)", g, what);
        return -1;
    }
    lx->p = q;
    return 0;
}

static const char *vector_form(int count) { return count == 2 ? "(w,h)" : "(x,y,z)"; }

int lx_vector(Lexer *lx, const char *what, double *v, int count, char *err, size_t n)
{
    char g[80];
    int i;
    if (!lx_accept(lx, '(')) {
        got(lx, g, sizeof g);
        snprintf(err, n, "'%s' needs a vector %s, %s", what, vector_form(count), g);
        return -1;
    }
    for (i = 0; i < count; i++) {
        char sep = i + 1 < count ? ',' : ')';
        if (lx_number(lx, what, &v[i], err, n) != 0) return -1;
        if (lx_accept(lx, sep)) continue;
        if (lx_at_end(lx)) snprintf(err, n, "missing ')' in the vector for '%s'", what);
        else if (*lx->p == ',' || *lx->p == ')')
            snprintf(err, n, "the vector for '%s' needs %d numbers %s", what, count, vector_form(count));
        else {
            got(lx, g, sizeof g);
            snprintf(err, n, "expected '%c' in the vector for '%s', %s", sep, what, g);
        }
        return -1;
    }
    return 0;
}

int lx_uint64(Lexer *lx, const char *what, unsigned long long *v, char *err, size_t n)
{
    const char *q;
    char g[80];
    unsigned long long x = 0;
    lx_skip_blanks(lx);
    for (q = lx->p; q < lx->end && is_digit(*q); q++) {
        unsigned d = (unsigned)(*q - '0');
        if (x > (18446744073709551615ULL - d) / 10) {
            lx_quote(g, sizeof g, lx->p, lx_token_len(lx));
            snprintf(err, n, "%s must be an integer 0..18446744073709551615 (got %s)", what, g);
            return -1;
        }
        x = x * 10 + d;
    }
    if (q == lx->p || !ends_number(lx, q)) {
        got(lx, g, sizeof g);
        snprintf(err, n, "'%s' needs an integer 0..18446744073709551615, %s", what, g);
        return -1;
    }
    *v = x;
    lx->p = q;
    return 0;
}

void lx_rest(Lexer *lx, const char **s, size_t *len)
{
    lx_skip_blanks(lx);
    *s = lx->p;
    *len = (size_t)(lx->end - lx->p);   /* lx_clean trimmed the end */
    lx->p = lx->end;
}

void lx_word(Lexer *lx, const char **s, size_t *len)
{
    lx_skip_blanks(lx);
    *s = lx->p;
    while (lx->p < lx->end && !is_blank(*lx->p)) lx->p++;
    *len = (size_t)(lx->p - *s);
}

static int fold(char c) { return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c; }

/* optimal string alignment distance (Levenshtein plus adjacent swaps) */
static int osa_distance(const char *a, size_t la, const char *b, size_t lb)
{
    int d[65][65];
    size_t i, j;
    for (i = 0; i <= la; i++) d[i][0] = (int)i;
    for (j = 0; j <= lb; j++) d[0][j] = (int)j;
    for (i = 1; i <= la; i++)
        for (j = 1; j <= lb; j++) {
            int cost = fold(a[i - 1]) != fold(b[j - 1]);
            int best = d[i - 1][j - 1] + cost;
            if (d[i - 1][j] + 1 < best) best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best) best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && fold(a[i - 1]) == fold(b[j - 2]) && fold(a[i - 2]) == fold(b[j - 1])
                && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[la][lb];
}

const char *lx_suggest(const char *word, size_t len, const char *const *cands, int ncands)
{
    const char *best = NULL;
    int bestd = len <= 4 ? 1 : 2, i;   /* farther than this is a different word */
    if (len == 0 || len > 64) return NULL;
    for (i = 0; i < ncands; i++) {
        size_t lc = strlen(cands[i]);
        int dist;
        if (lc > 64) continue;
        dist = osa_distance(word, len, cands[i], lc);
        if (dist < bestd || (dist == bestd && !best)) {
            best = cands[i];
            bestd = dist;
        }
    }
    return best;
}
