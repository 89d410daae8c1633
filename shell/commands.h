/* commands.h — the one static table of commands and attributes.  It drives
 * parsing and range checks, dispatch, `help`, TAB completion and the
 * man-page test (tests/man.sh reads `help`). */
#ifndef VROC_COMMANDS_H
#define VROC_COMMANDS_H

#include "shell.h"

/* the shape of a statement after its first word */
typedef enum Form {
    F_BARE,        /* nothing follows: `start` */
    F_COUNT,       /* an optional integer: `step [n]` */
    F_INT,         /* an integer: `random N` */
    F_NAME,        /* an object name: `sphere NAME`, `show NAME` */
    F_TOPIC,       /* an optional word: `help [CMD]` */
    F_PATH,        /* the rest of the line: `read FILE` */
    F_ASSIGN       /* `= value` of kind Kind */
} Form;

typedef enum Kind {
    K_NONE,
    K_NUM,         /* a number in range */
    K_INT,         /* an integer in range */
    K_VEC3,        /* (x,y,z), each component in range (R_NONZERO: the vector) */
    K_IVEC3,       /* (r,g,b) integers in range */
    K_IVEC2,       /* (w,h) integers in range */
    K_AXIS,        /* (x,y,z) m: a non-zero vector and a number in range */
    K_SCALE,       /* s or (x,y,z): three numbers in range, one given for all */
    K_TEXT,        /* the rest of the line (path or name); may be empty when allow_empty */
    K_WORD,        /* one word without blanks */
    K_CHOICE,      /* one of choices[] */
    K_UINT64       /* 0..2^64-1 */
} Kind;

/* R_MASS: negative (static), or lo..hi */
typedef enum Range { R_ANY, R_GT, R_GE, R_CLOSED, R_NONZERO, R_MASS } Range;

/* where an attribute lives */
typedef enum Target { T_NONE, T_OBJECT, T_SETTINGS, T_VIEW } Target;

/* type masks for object attributes */
#define TY_SPHERE (1u << VR_SPHERE)
#define TY_CUBE (1u << VR_CUBE)
#define TY_SQ (1u << VR_SUPERQUADRIC)
#define TY_POLY (1u << VR_POLYHEDRON)
#define TY_ALL (TY_SPHERE | TY_CUBE | TY_SQ | TY_POLY)

typedef enum Group { G_OBJECT, G_ATTR, G_SYSTEM, G_EXT, G_VIEW, G_NGROUPS } Group;

typedef struct Stmt Stmt;
typedef struct Command Command;
typedef int (*RunFn)(Shell *sh, const Stmt *st, char *err, size_t n);

struct Command {
    const char *name;
    const char *syntax;        /* as help shows it: "radius = r" */
    const char *help;          /* one line */
    const char *deflt;         /* the default, as text; NULL: none */
    Group group;
    Form form;
    Kind kind;
    Range range;
    double lo, hi;             /* R_GT/R_GE: lo (hi: largest accepted); R_CLOSED: lo..hi */
    int allow_empty;           /* K_TEXT: an empty value is allowed */
    const char *const *choices;/* K_CHOICE */
    Target target;
    size_t offset;             /* of the field in vrObjectDef, vrSettings or vrView */
    unsigned types;            /* T_OBJECT: the object types it applies to */
    RunFn run;
};

struct Stmt {
    const Command *cmd;
    double v[4];               /* numbers, vector components; K_AXIS: v[3] is the scalar */
    int has_value;             /* F_COUNT/F_TOPIC: something was given */
    unsigned long long u;      /* K_UINT64 */
    const char *text;          /* K_TEXT, K_WORD, F_PATH, F_TOPIC: into the line */
    size_t textlen;
    int choice;                /* K_CHOICE: index into choices */
    char name[VR_NAME_MAX + 1];/* F_NAME */
};

extern const Command sh_commands[];
extern const int sh_ncommands;

const Command *sh_find_command(const char *name, size_t len);
/* the allowed range of a command's value, as text ("> 0", "3..1000 (integer)") */
void sh_range_text(const Command *c, char *buf, size_t n);
/* the names of all commands, in table order, for did-you-mean and completion */
const char *const *sh_command_names(void);
int sh_print_help(Shell *sh, const Stmt *st, char *err, size_t n);

/* K_NUM, K_INT, K_VEC3, K_AXIS (its vector), K_IVEC3 values into the
 * field at the command's offset in base (objects.c) */
void sh_store_number(void *base, const Stmt *st);

/* handlers, by module */
/* objects.c */
int run_object(Shell *sh, const Stmt *st, char *err, size_t n);
int run_attr(Shell *sh, const Stmt *st, char *err, size_t n);
int run_show(Shell *sh, const Stmt *st, char *err, size_t n);
int run_delete(Shell *sh, const Stmt *st, char *err, size_t n);
int run_random(Shell *sh, const Stmt *st, char *err, size_t n);
/* settings.c */
int run_setting(Shell *sh, const Stmt *st, char *err, size_t n);
int run_gravity(Shell *sh, const Stmt *st, char *err, size_t n);
int run_view(Shell *sh, const Stmt *st, char *err, size_t n);
int run_reset(Shell *sh, const Stmt *st, char *err, size_t n);
int run_frames(Shell *sh, const Stmt *st, char *err, size_t n);
int run_frames_format(Shell *sh, const Stmt *st, char *err, size_t n);
int run_dump(Shell *sh, const Stmt *st, char *err, size_t n);
int run_stats(Shell *sh, const Stmt *st, char *err, size_t n);
/* simulate.c */
int run_start(Shell *sh, const Stmt *st, char *err, size_t n);
int run_stop(Shell *sh, const Stmt *st, char *err, size_t n);
int run_step(Shell *sh, const Stmt *st, char *err, size_t n);
int run_restart(Shell *sh, const Stmt *st, char *err, size_t n);
/* frames.c */
int run_display(Shell *sh, const Stmt *st, char *err, size_t n);
/* sound.c */
int run_sound_log(Shell *sh, const Stmt *st, char *err, size_t n);
/* track.c */
int run_track(Shell *sh, const Stmt *st, char *err, size_t n);
int run_trackers(Shell *sh, const Stmt *st, char *err, size_t n);
/* the view a frame is drawn with: the settings', or the tracked head's */
vrView sh_current_view(const Shell *sh);
/* save.c */
int run_save(Shell *sh, const Stmt *st, char *err, size_t n);
int run_state(Shell *sh, const Stmt *st, char *err, size_t n);
/* window.c */
int run_window(Shell *sh, const Stmt *st, char *err, size_t n);
int run_window_mode(Shell *sh, const Stmt *st, char *err, size_t n);
/* source.c */
int run_read(Shell *sh, const Stmt *st, char *err, size_t n);
int run_quit(Shell *sh, const Stmt *st, char *err, size_t n);

#endif
