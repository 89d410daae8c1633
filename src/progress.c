/* progress.c — the process's "still working" hook (progress.h). */
#include <stddef.h>
#include "progress.h"

static void (*hook)(void *);
static void *hook_ctx;
static unsigned ticks;

void vrProgress_Set(void (*fn)(void *), void *ctx)
{
    hook = fn;
    hook_ctx = ctx;
    ticks = 0;
}

void vrProgress_Tick(void)
{
    if (hook && ++ticks % VR_PROGRESS_EVERY == 0) hook(hook_ctx);
}

void vrProgress_Now(void)
{
    if (hook) hook(hook_ctx);
}
