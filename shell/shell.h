/* shell.h — the state of one `vroc` session, shared by the shell's modules.
 *
 * The shell is a client of include/vroc.h only.  One Shell lives for the
 * whole process; every statement, whatever its source (a file on the
 * command line, a `read`, stdin, the prompt), goes through sh_exec_line.
 */
#ifndef VROC_SHELL_H
#define VROC_SHELL_H

#include <stddef.h>
#include <signal.h>
#include <stdio.h>
#include <sys/types.h>
#include "vroc.h"

#define SH_ERR_MAX 1200          /* one error message */
#define SH_READ_DEPTH_MAX 64     /* nested `read`: a cycle is caught earlier, this is a backstop */

/* One input being read: what messages name, and where relative paths in
 * it start from.  Sources form a chain through `read`. */
typedef struct Source {
    char name[VR_PATH_MAX];      /* "<stdin>", or the file's path as resolved */
    char dir[VR_PATH_MAX];       /* folder of the file; "" for stdin and the prompt */
    long line;                   /* the line being executed, from 1 */
    dev_t dev;                   /* identity of the file, to refuse read cycles */
    ino_t ino;
    int has_id;
    struct Source *parent;       /* the source whose `read` opened this one */
    int depth;
} Source;

typedef struct Shell {
    vrWorld *world;
    vrView view;                 /* head pose and stereo parameters (SPEC 4) */
    vrDisplay *display;          /* NULL until something needs it */
    char frames_dir[VR_PATH_MAX];/* "" : frames are not written */
    vrFrameFormat frames_format; /* PPM (the default) or PNG */
    struct ShWindow *window;     /* the live window (window.c); NULL: none */
    vrWindowMode window_mode;
    vrObjectId selected;         /* the object that attribute statements edit */
    int interactive;             /* a person at a terminal: `start` runs in real time */
    int quiet;                   /* -q: no notes */
    int bail;                    /* -b: stop at the first error */
    int bailing;                 /* an error happened under -b: stop reading */
    int quit;                    /* `quit` was executed */
    int running;                 /* a real-time `start` is going on */
    char run_origin[VR_PATH_MAX + 32]; /* "FILE:LINE" of that `start`, for its errors */
    double next_frame;           /* monotonic seconds when the next real-time frame is due */
    vrTrackers *trackers;        /* `trackers = URL`, NULL: none (track.c) */
    FILE *sound_log;             /* `sound_log = FILE`, NULL: none (sound.c) */
    long errors;                 /* errors so far: the exit status */
    int clamp_noted;             /* the note on the first speed clamp was given (or a cap was set) */
    Source *src;                 /* the innermost source being read */
} Shell;

/* errors.c: `vroc: FILE:LINE: message (read at ...)` on stderr */
void sh_error(Shell *sh, const char *fmt, ...);
void sh_note(Shell *sh, const char *fmt, ...);
/* an error that belongs to an earlier line (`start` running in real time) */
void sh_error_at(Shell *sh, const char *origin, const char *msg);
/* where the current statement comes from, as "FILE:LINE" */
void sh_location(const Shell *sh, char *buf, size_t n);
/* a path in the current source: relative paths start from its folder */
int sh_resolve_path(const Shell *sh, const char *path, size_t len, char *out, size_t n);

/* commands.c: one line of input, parsed whole and then executed */
int sh_exec_line(Shell *sh, char *line, size_t len);

/* source.c: reading statements from files and streams */
int sh_read_file(Shell *sh, const char *path, char *err, size_t n);
int sh_read_stream(Shell *sh, FILE *f, Source *src);
void sh_source_init(Source *src, const char *name, const char *dir);

/* interactive.c: the prompt, line editing, history, real time */
int sh_interactive(Shell *sh);

/* simulate.c: frames */
/* seconds until the next real-time frame is due (0: now), or -1 when
 * nothing runs */
double sh_frame_wait(const Shell *sh);
/* runs the due real-time frame; an error stops the run and is returned */
int sh_tick(Shell *sh, char *err, size_t n);
extern volatile sig_atomic_t sh_interrupted;   /* SIGINT: stop a long `step` */

/* track.c: live trackers (SPEC 8) */
#define SH_TRACKER_DEADLINE 1.0      /* s of wall time a script waits for a silent tracker */
#define SH_TRACKER_FIRST_WAIT 5.0    /* s a script's `trackers =` waits for the first sample */
void sh_trackers_before_frame(Shell *sh);
/* `show head`, `show hand`: 1 when name is one of them (printed) */
int sh_show_tracker(Shell *sh, const char *name);

/* sound.c: the collision sound log (SPEC 8) */
int sh_sound_frame(Shell *sh, char *err, size_t n);
void sh_sound_close(Shell *sh);

/* frames.c: the frames drawn and written (SPEC 4) */
int sh_display_open(Shell *sh, char *err, size_t n);
int sh_display_draw(Shell *sh, char *err, size_t n);
void sh_display_close(Shell *sh);

/* window.c: the live window (SPEC 9), serviced whenever the shell waits */
/* reads its input and shows the current frame when it changed; no-op
 * without a window */
void sh_window_service(Shell *sh);
/* a new frame: shown at the next service */
void sh_window_frame(Shell *sh);
/* waits until fd has input, servicing the window and running real-time
 * frames meanwhile; at once when neither is there */
void sh_wait_input(Shell *sh, int fd);
/* seconds the prompt may sleep before the window needs servicing, -1: any */
double sh_window_wait(const Shell *sh);
void sh_window_close(Shell *sh);

/* simulate.c: a real-time run (the prompt's `start`, the window's space key) */
int sh_run_realtime(Shell *sh, char *err, size_t n);

/* panel.c: the virtual tool panel (SPEC 8) */
/* the frames a command still runs: `step n` counts down; a `start`
 * (until_rest) also ends when everything rests */
typedef struct ShRun {
    long left;
    int until_rest;
} ShRun;
/* after a frame: the panel's stop, play and step presses change the run */
void sh_panel_requests(Shell *sh, ShRun *run);
/* `show panel`: 1 when name is `panel` (printed) */
int sh_show_panel(Shell *sh, const char *name);
/* `panel` is a reserved word for show, not an object name */
int sh_reserved_name(const char *name);

#endif
