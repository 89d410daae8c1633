/* netns.h — UDP multicast only inside a private network namespace (nothing
 * may leave the machine): the test runner (tests/main.c, when a suite
 * marked netns is selected) or a benchmark that uses udpm re-executes
 * itself under `unshare -n` with lo up and a multicast route on it, and
 * fails loudly when it cannot (it never skips). */
#ifndef VROC_NETNS_H
#define VROC_NETNS_H

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static void enter_namespace(int argc, char **argv)
{
    char *args[16];
    int i, k = 0;
    if (getenv("VROC_NETNS")) return;
    args[k++] = "unshare";
    args[k++] = "-n";
    args[k++] = "sh";
    args[k++] = "-c";
    args[k++] = "ip link set lo up && ip link set lo multicast on && ip route add 224.0.0.0/4 dev lo "
                "&& VROC_NETNS=1 exec \"$0\" \"$@\" "
                "|| { echo 'FAIL cannot make a private network namespace (unshare -n needs root)'; "
                "echo '0 passed, 1 failed'; exit 1; }";
    for (i = 0; i < argc && k < 15; i++) args[k++] = argv[i];
    args[k] = NULL;
    execvp("unshare", args);
    printf("FAIL cannot run unshare: UDP multicast needs a private network namespace\n0 passed, 1 failed\n");
    exit(1);
}

#endif
