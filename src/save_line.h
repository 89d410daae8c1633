/* save_line.h — the text of a saved file's `state` lines (SPEC 11):
 * `state WORD key=value key=value ...`, a value a number, an integer, a
 * name or a vector `(a, b, c)`.  Numbers are written as the shortest
 * decimal that reads back to the same bits (-0 kept, infinities as inf),
 * so a saved file is readable, editable and exact; hex floats (%a) read
 * too.  A line is parsed whole; each section then takes its keys, and a
 * key given twice, missing, or unknown is an error naming it. */
#ifndef VROC_SAVE_LINE_H
#define VROC_SAVE_LINE_H

#include <stddef.h>
#include <stdio.h>

#define VR_SAVE_KEYS 48

typedef struct vrSaveField {
    const char *key, *val;
    size_t klen, vlen;
    int used;
} vrSaveField;

typedef struct vrSaveLine {
    const char *word;            /* the section's word, for messages */
    int n;
    vrSaveField f[VR_SAVE_KEYS];
} vrSaveLine;

/* the key=value pairs of text (what follows the section word) */
int vrSaveLine_Parse(vrSaveLine *l, const char *word, const char *text, size_t len, char *err, size_t n);
/* count finite numbers (or, with allow_inf, infinities too): a number
 * when count is 1, else a vector of count */
int vrSaveLine_Numbers(vrSaveLine *l, const char *key, double *v, int count, int allow_inf, char *err, size_t n);
int vrSaveLine_Integer(vrSaveLine *l, const char *key, long long lo, long long hi, long long *v, char *err, size_t n);
int vrSaveLine_U64(vrSaveLine *l, const char *key, unsigned long long *v, char *err, size_t n);
/* a word (an object's name) into buf */
int vrSaveLine_Word(vrSaveLine *l, const char *key, char *buf, size_t size, char *err, size_t n);
/* 1 when key is on the line */
int vrSaveLine_Has(const vrSaveLine *l, const char *key);
/* every key of the line is among keys (blank-separated): 0, or an error
 * naming the first that is not */
int vrSaveLine_Known(const vrSaveLine *l, const char *keys, char *err, size_t n);
/* every key was taken: 0, or an error naming the first one that was not */
int vrSaveLine_Done(const vrSaveLine *l, char *err, size_t n);

/* writers: " key=value" */
void vrSave_Number(FILE *out, const char *key, double x);
void vrSave_Vector(FILE *out, const char *key, const double *v, int count);
void vrSave_Integer(FILE *out, const char *key, long long x);

#endif
