/* vroc-gp — a VROC worker (a GP of thesis 3.5) started by hand, for an SGP
 * on another host: `vroc-gp 'udpm://239.255.76.67:7667?ttl=1'`.  The shell
 * forks its own workers when its lcm_url keeps traffic on this host. */
#include <stdio.h>
#include <string.h>
#include "vroc.h"

int main(int argc, char **argv)
{
    char err[512];
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("vroc-gp %s\n", VROC_VERSION);
        return 0;
    }
    if (argc != 2 || argv[1][0] == '-') {
        fprintf(stderr, "usage: vroc-gp LCM_URL   (e.g. 'udpm://239.255.76.67:7667?ttl=1')\n");
        return 2;
    }
    if (vrWorker_Run(argv[1], err, sizeof err) != 0) {
        fprintf(stderr, "vroc-gp: %s\n", err);
        return 1;
    }
    return 0;
}
