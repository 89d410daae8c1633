/* save_line.c — `state` lines as text (save_line.h).
 *   vrFormatExact      a double as the shortest decimal with its bits
 *   scan_field         one key=value
 *   find, number_at    a key's field; one number of a value
 *   vrSaveLine_*       the getters a section takes its keys with
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "vroc.h"
#include "save_line.h"

void vrFormatExact(char buf[32], double x)
{
    int prec;
    if (isinf(x)) {
        snprintf(buf, 32, "%s", x < 0 ? "-inf" : "inf");
        return;
    }
    for (prec = 1; prec <= 17; prec++) {
        snprintf(buf, 32, "%.*g", prec, x);
        if (strtod(buf, NULL) == x && signbit(strtod(buf, NULL)) == signbit(x)) return;
    }
}

static int is_blank(char c) { return c == ' ' || c == '\t'; }

static int fail(char *err, size_t n, const char *fmt, const char *word, const char *key, size_t klen)
{
    char k[80];
    snprintf(k, sizeof k, "%.*s", (int)(klen > 60 ? 60 : klen), key);
    snprintf(err, n, fmt, word, k);
    return -1;
}

/* key=value at *p; a vector's value runs to its ')' */
static int scan_field(vrSaveLine *l, const char **p, const char *end, char *err, size_t n)
{
    vrSaveField *f = &l->f[l->n];
    const char *s = *p;
    f->key = s;
    while (s < end && *s != '=' && !is_blank(*s)) s++;
    f->klen = (size_t)(s - f->key);
    if (s == end || *s != '=' || f->klen == 0)
        return fail(err, n, "state %s: expected key=value, got '%s'", l->word, f->key, f->klen ? f->klen : 1);
    f->val = ++s;
    if (s < end && *s == '(') {
        while (s < end && *s != ')') s++;
        if (s == end) return fail(err, n, "state %s: '%s' has no closing ')'", l->word, f->key, f->klen);
        s++;
    } else
        while (s < end && !is_blank(*s)) s++;
    f->vlen = (size_t)(s - f->val);
    if (f->vlen == 0) return fail(err, n, "state %s: '%s' has no value", l->word, f->key, f->klen);
    f->used = 0;
    l->n++;
    *p = s;
    return 0;
}

int vrSaveLine_Parse(vrSaveLine *l, const char *word, const char *text, size_t len, char *err, size_t n)
{
    const char *p = text, *end = text + len;
    int i;
    l->word = word;
    l->n = 0;
    for (;;) {
        while (p < end && is_blank(*p)) p++;
        if (p == end) return 0;
        if (l->n == VR_SAVE_KEYS) return fail(err, n, "state %s: more than 48 keys%s", word, "", 0);
        if (scan_field(l, &p, end, err, n) != 0) return -1;
        for (i = 0; i < l->n - 1; i++)
            if (l->f[i].klen == l->f[l->n - 1].klen && memcmp(l->f[i].key, l->f[l->n - 1].key, l->f[i].klen) == 0)
                return fail(err, n, "state %s: '%s' is given twice", word, l->f[i].key, l->f[i].klen);
    }
}

static vrSaveField *find(vrSaveLine *l, const char *key, char *err, size_t n)
{
    int i;
    for (i = 0; i < l->n; i++)
        if (l->f[i].klen == strlen(key) && memcmp(l->f[i].key, key, l->f[i].klen) == 0) {
            l->f[i].used = 1;
            return &l->f[i];
        }
    fail(err, n, "state %s: '%s' is missing", l->word, key, strlen(key));
    return NULL;
}

int vrSaveLine_Has(const vrSaveLine *l, const char *key)
{
    int i;
    for (i = 0; i < l->n; i++)
        if (l->f[i].klen == strlen(key) && memcmp(l->f[i].key, key, l->f[i].klen) == 0) return 1;
    return 0;
}

static int bad_value(const vrSaveLine *l, const vrSaveField *f, const char *what, char *err, size_t n)
{
    snprintf(err, n, "state %s: %.*s must be %s (got '%.*s')", l->word, (int)f->klen, f->key, what,
             (int)(f->vlen > 60 ? 60 : f->vlen), f->val);
    return -1;
}

/* one number of a value at *p, which moves past it */
static int number_at(const char **p, const char *end, double *x, int allow_inf)
{
    char buf[64], *stop;
    size_t k = 0;
    while (*p < end && is_blank(**p)) (*p)++;
    while (*p < end && k + 1 < sizeof buf && **p != ',' && **p != ')' && !is_blank(**p)) buf[k++] = *(*p)++;
    buf[k] = '\0';
    if (k == 0) return -1;
    errno = 0;
    *x = strtod(buf, &stop);
    if (*stop != '\0' || isnan(*x) || (isinf(*x) && !allow_inf)) return -1;
    while (*p < end && is_blank(**p)) (*p)++;
    return 0;
}

int vrSaveLine_Numbers(vrSaveLine *l, const char *key, double *v, int count, int allow_inf, char *err, size_t n)
{
    vrSaveField *f = find(l, key, err, n);
    const char *p, *end;
    int i;
    if (!f) return -1;
    p = f->val, end = f->val + f->vlen;
    if (count == 1) {
        if (number_at(&p, end, v, allow_inf) != 0 || p != end) return bad_value(l, f, "a number", err, n);
        return 0;
    }
    if (*p++ != '(') return bad_value(l, f, "a vector (a, b, ...)", err, n);
    for (i = 0; i < count; i++) {
        if (number_at(&p, end, &v[i], allow_inf) != 0 || p == end || *p != (i + 1 < count ? ',' : ')'))
            return bad_value(l, f, count == 3 ? "a vector of 3 finite numbers" : "a vector of 4 finite numbers", err, n);
        p++;
    }
    return p == end ? 0 : bad_value(l, f, "one vector", err, n);
}

int vrSaveLine_Integer(vrSaveLine *l, const char *key, long long lo, long long hi, long long *v, char *err, size_t n)
{
    vrSaveField *f = find(l, key, err, n);
    char buf[32], *stop, what[96];
    if (!f) return -1;
    snprintf(what, sizeof what, "an integer %lld..%lld", lo, hi);
    if (f->vlen >= sizeof buf) return bad_value(l, f, what, err, n);
    memcpy(buf, f->val, f->vlen);
    buf[f->vlen] = '\0';
    errno = 0;
    *v = strtoll(buf, &stop, 10);
    if (*stop != '\0' || errno || *v < lo || *v > hi) return bad_value(l, f, what, err, n);
    return 0;
}

int vrSaveLine_U64(vrSaveLine *l, const char *key, unsigned long long *v, char *err, size_t n)
{
    vrSaveField *f = find(l, key, err, n);
    char buf[32], *stop;
    if (!f) return -1;
    if (f->vlen >= sizeof buf || f->val[0] < '0' || f->val[0] > '9') return bad_value(l, f, "an integer 0..2^64-1", err, n);
    memcpy(buf, f->val, f->vlen);
    buf[f->vlen] = '\0';
    errno = 0;
    *v = strtoull(buf, &stop, 10);
    if (*stop != '\0' || errno) return bad_value(l, f, "an integer 0..2^64-1", err, n);
    return 0;
}

int vrSaveLine_Word(vrSaveLine *l, const char *key, char *buf, size_t size, char *err, size_t n)
{
    vrSaveField *f = find(l, key, err, n);
    if (!f) return -1;
    if (f->vlen >= size) return bad_value(l, f, "a name", err, n);
    memcpy(buf, f->val, f->vlen);
    buf[f->vlen] = '\0';
    return 0;
}

static int among(const char *keys, const char *key, size_t len)
{
    const char *p = keys;
    while (*p) {
        size_t k = strcspn(p, " ");
        if (k == len && memcmp(p, key, len) == 0) return 1;
        p += k;
        p += strspn(p, " ");
    }
    return 0;
}

int vrSaveLine_Known(const vrSaveLine *l, const char *keys, char *err, size_t n)
{
    int i;
    for (i = 0; i < l->n; i++)
        if (!among(keys, l->f[i].key, l->f[i].klen))
            return fail(err, n, "state %s: unknown key '%s'", l->word, l->f[i].key, l->f[i].klen);
    return 0;
}

int vrSaveLine_Done(const vrSaveLine *l, char *err, size_t n)
{
    int i;
    for (i = 0; i < l->n; i++)
        if (!l->f[i].used) return fail(err, n, "state %s: unknown key '%s'", l->word, l->f[i].key, l->f[i].klen);
    return 0;
}

void vrSave_Number(FILE *out, const char *key, double x)
{
    char b[32];
    vrFormatExact(b, x);
    fprintf(out, " %s=%s", key, b);
}

void vrSave_Vector(FILE *out, const char *key, const double *v, int count)
{
    char b[32];
    int i;
    fprintf(out, " %s=(", key);
    for (i = 0; i < count; i++) {
        vrFormatExact(b, v[i]);
        fprintf(out, "%s%s", i ? ", " : "", b);
    }
    fputc(')', out);
}

void vrSave_Integer(FILE *out, const char *key, long long x) { fprintf(out, " %s=%lld", key, x); }
