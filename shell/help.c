/* help.c — `help` and `help NAME`, printed from the command table.
 * tests/man.sh reads this listing: every line that starts with two
 * blanks names one command by its first word. */
#include <stdio.h>
#include <string.h>
#include "commands.h"
#include "lexer.h"

#define SYNTAX_WIDTH 24

static const char *const group_titles[G_NGROUPS] = {
    "objects (thesis tables A.1-A.4): create, or select when NAME exists",
    "attributes of the selected object [default; range]",
    "system (thesis table A.5) [default; range]",
    "extensions [default; range]",
    "display and head pose (frames are written once a display is open) [default; range]",
};

static const char *const type_names[] = {"sphere", "cube", "superquadric", "polyhedron"};

static void print_entry(const Command *c)
{
    char range[96];
    sh_range_text(c, range, sizeof range);
    /* a syntax too wide for its column gets a line of its own */
    if (strlen(c->syntax) > SYNTAX_WIDTH) printf("  %s\n  %-*s %s", c->syntax, SYNTAX_WIDTH, "", c->help);
    else printf("  %-*s %s", SYNTAX_WIDTH, c->syntax, c->help);
    if (c->deflt && range[0]) printf(" [%s; %s]", c->deflt, range);
    else if (c->deflt) printf(" [%s]", c->deflt);
    else if (range[0]) printf(" [%s]", range);
    putchar('\n');
}

static void print_all(void)
{
    int g, i;
    printf("vroc %s commands (help NAME for one; man vroc for the manual):\n", VROC_VERSION);
    for (g = 0; g < G_NGROUPS; g++) {
        printf("\n%s\n", group_titles[g]);
        for (i = 0; i < sh_ncommands; i++)
            if (sh_commands[i].group == (Group)g) print_entry(&sh_commands[i]);
    }
}

static void print_types(unsigned types)
{
    int t, first = 1;
    printf("    applies to:");
    for (t = VR_SPHERE; t <= VR_POLYHEDRON; t++)
        if (types & (1u << t)) {
            printf("%s %s", first ? "" : ",", type_names[t]);
            first = 0;
        }
    putchar('\n');
}

static void print_one(const Command *c)
{
    char range[96];
    sh_range_text(c, range, sizeof range);
    printf("%s\n    %s\n", c->syntax, c->help);
    if (c->deflt) printf("    default: %s\n", c->deflt);
    if (range[0]) printf("    range: %s\n", range);
    if (c->target == T_OBJECT) print_types(c->types);
}

int sh_print_help(Shell *sh, const Stmt *st, char *err, size_t n)
{
    const Command *c;
    const char *near;
    char q[80];
    (void)sh;
    if (!st->has_value) {
        print_all();
        return 0;
    }
    c = sh_find_command(st->text, st->textlen);
    if (c) {
        print_one(c);
        return 0;
    }
    lx_quote(q, sizeof q, st->text, st->textlen);
    near = lx_suggest(st->text, st->textlen, sh_command_names(), sh_ncommands);
    if (near) snprintf(err, n, "no help for %s (did you mean '%s'?)", q, near);
    else snprintf(err, n, "no help for %s (help lists the commands)", q);
    return -1;
}
