/* module.c — finding and loading a module (module.h). */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "module.h"
#include "render.h"

#ifndef VROC_LIBDIR
#define VROC_LIBDIR "/usr/local/lib/vroc"
#endif

/* the folder of the running executable, "" when unknown */
static void exe_dir(char *dir, size_t len)
{
    ssize_t n = readlink("/proc/self/exe", dir, len - 1);
    char *slash;
    dir[n > 0 ? n : 0] = '\0';
    slash = strrchr(dir, '/');
    if (slash) *slash = '\0';
    else dir[0] = '\0';
}

static int find_module(const char *file, char *path, size_t len)
{
    static const char *const rel[] = {"/", "/../", "/../lib/vroc/"};
    char dir[4096];
    size_t i;
    exe_dir(dir, sizeof dir);
    for (i = 0; dir[0] && i < sizeof rel / sizeof rel[0]; i++) {
        snprintf(path, len, "%s%s%s", dir, rel[i], file);
        if (access(path, F_OK) == 0) return 0;
    }
    snprintf(path, len, "%s/%s", VROC_LIBDIR, file);
    return access(path, F_OK) == 0 ? 0 : -1;
}

const void *vrModule_Load(const char *what, const char *file, const char *env, const char *symbol,
                          char *err, size_t errlen)
{
    const char *given = getenv(env);
    char path[4200];
    void *h, *sym;
    if (given && given[0]) {
        snprintf(path, sizeof path, "%s", given);
    } else if (find_module(file, path, sizeof path)) {
        vrRender_Error(err, errlen, "cannot find the %s %s (looked beside the executable, in its "
                "parent folder, in ../lib/vroc and in " VROC_LIBDIR "); set %s to its path", what, file, env);
        return NULL;
    }
    h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        vrRender_Error(err, errlen, "cannot load the %s: %s", what, dlerror());
        return NULL;
    }
    sym = dlsym(h, symbol);
    if (!sym) {
        vrRender_Error(err, errlen, "%s is not a %s of this build (no %s); rebuild it", path, what, symbol);
        dlclose(h);
    }
    return sym;
}
