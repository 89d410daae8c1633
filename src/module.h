/* module.h — the modules the library loads on first use (dlopen), so that a
 * run which never needs them never loads what they link: vroc-render.so
 * (OSMesa, LLVM) and vroc-window.so (GLFW, GL, X11).
 *
 * Where a module FILE is looked for, first found wins:
 *   $ENV (a path to the .so; when set, the only place looked)
 *   beside the running executable (readlink /proc/self/exe)
 *   the executable's parent folder (tests run from build/<variant>/tests/)
 *   <executable>/../lib/vroc (an installed tree: PREFIX/bin, PREFIX/lib/vroc)
 *   VROC_LIBDIR, /usr/local/lib/vroc unless the build defines it
 * A module stays loaded until the process ends: OSMesa, LLVM and GLX
 * register exit handlers and thread state that do not survive a dlclose. */
#ifndef VROC_MODULE_H
#define VROC_MODULE_H

#include <stddef.h>

/* the module's data symbol (a struct of function pointers: ISO C has no
 * conversion from dlsym's void * to a function pointer), or NULL and a
 * message naming WHAT ("render module"), the file and why */
const void *vrModule_Load(const char *what, const char *file, const char *env, const char *symbol,
                          char *err, size_t errlen);

#endif
