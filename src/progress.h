/* progress.h — "still working": a long computation in a worker process
 * (a fine superquadric's hull: 4 s at ures = vres = 1000) ticks, and the
 * process's hook, the worker's heartbeat, tells its SGP it is not dead
 * (SPEC 5's deadline is 1 s).  One hook per process, set only by a worker
 * running in a process of its own (parallel/worker.c); unset, a tick costs
 * a test. */
#ifndef VROC_PROGRESS_H
#define VROC_PROGRESS_H

/* fn(ctx) is called at ticks (NULL: none) */
void vrProgress_Set(void (*fn)(void *), void *ctx);
/* a step of a long computation: the hook is called every VR_PROGRESS_EVERY ticks */
void vrProgress_Tick(void);
/* a stage of one: the hook now */
void vrProgress_Now(void);

#define VR_PROGRESS_EVERY 256

#endif
