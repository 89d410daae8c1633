/* help.c — `help` and `help NAME`, printed from the command table, in 80
 * columns (a terminal's width; text wraps under its column).
 * tests/man.sh reads this listing: every line that starts with two
 * blanks and a letter names one command by its first word; wrapped lines
 * start with more blanks. */
#include <stdio.h>
#include <string.h>
#include "commands.h"
#include "lexer.h"

#define SYNTAX_WIDTH 24
#define TEXT_COLUMN (2 + SYNTAX_WIDTH + 1)
#define LINE_WIDTH 80

static const char *const group_titles[G_NGROUPS] = {
    "objects (thesis tables A.1-A.4): create, or select when NAME exists",
    "attributes of the selected object",
    "system (thesis table A.5)",
    "extensions",
    "display and head pose (frames are written once a display is open)",
};

/* text from column `at` (the cursor is there) to LINE_WIDTH, broken at
 * blanks, each further line indented to `indent` */
static void put_wrapped(const char *text, int at, int indent)
{
    int col = at;
    while (*text) {
        int len = 0;
        while (*text == ' ') text++;
        while (text[len] && text[len] != ' ') len++;
        if (!len) break;
        if (col > indent && col + 1 + len > LINE_WIDTH - 1) {
            printf("\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
            putchar(' ');
            col++;
        }
        printf("%.*s", len, text);
        col += len;
        text += len;
    }
    putchar('\n');
}

static const char *const type_names[] = {"sphere", "cube", "superquadric", "polyhedron"};

static void print_entry(const Command *c)
{
    char range[96], text[400];
    int len;
    sh_range_text(c, range, sizeof range);
    len = snprintf(text, sizeof text, "%s", c->help);
    if (c->deflt && range[0]) snprintf(text + len, sizeof text - len, " [%s; %s]", c->deflt, range);
    else if (c->deflt) snprintf(text + len, sizeof text - len, " [%s]", c->deflt);
    else if (range[0]) snprintf(text + len, sizeof text - len, " [%s]", range);
    /* a syntax too wide for its column gets a line of its own */
    if (strlen(c->syntax) > SYNTAX_WIDTH) printf("  %s\n%*s", c->syntax, TEXT_COLUMN, "");
    else printf("  %-*s ", SYNTAX_WIDTH, c->syntax);
    put_wrapped(text, TEXT_COLUMN, TEXT_COLUMN);
}

static void print_all(void)
{
    int g, i;
    printf("vroc %s commands by group, each with [its default; its range].\n"
           "help NAME describes one; man vroc is the manual.\n", VROC_VERSION);
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
    printf("%s\n    ", c->syntax);
    put_wrapped(c->help, 4, 4);
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
