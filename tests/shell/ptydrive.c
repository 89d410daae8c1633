/* ptydrive.c — runs a program on a pseudo-terminal and drives it from a
 * script, for tests/tty.sh (no tmux or expect needed).
 *
 *   ptydrive TRANSCRIPT PROGRAM [ARG...] < SCRIPT
 *
 * SCRIPT lines:
 *   send TEXT      types TEXT (escapes: \n \r \t \e \\ \xHH)
 *   expect TEXT    waits until the output since the last expect contains TEXT
 *   sleep SECONDS  lets the program run
 *   # ...          a comment
 * At the end of the script ptydrive waits for the program to exit.  Every
 * byte the program wrote goes to TRANSCRIPT.  Exit status: the program's,
 * or 124 when an expect or the exit timed out (the program is killed), 125
 * for a bad script or setup.  Each wait gives up after 10 seconds.
 */
#define _XOPEN_SOURCE 600
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#define WAIT_MS 10000

static int master = -1;
static pid_t child;
static FILE *transcript;
static char seen[1 << 20];   /* output since the last successful expect */
static size_t nseen;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static void die(int status, const char *msg)
{
    fprintf(stderr, "ptydrive: %s\n", msg);
    if (child > 0) kill(child, SIGKILL);
    if (transcript) fclose(transcript);
    exit(status);
}

/* reads what is there within ms; 0 when the program closed the terminal */
static int pump(int ms)
{
    struct pollfd p;
    char buf[4096];
    ssize_t n;
    p.fd = master;
    p.events = POLLIN;
    if (poll(&p, 1, ms) <= 0) return 1;
    n = read(master, buf, sizeof buf);
    if (n <= 0) return 0;
    fwrite(buf, 1, (size_t)n, transcript);
    fflush(transcript);
    if (nseen + (size_t)n >= sizeof seen) nseen = 0;   /* keep the tail only */
    memcpy(seen + nseen, buf, (size_t)n);
    nseen += (size_t)n;
    return 1;
}

static int contains(const char *text, size_t len)
{
    size_t i;
    for (i = 0; i + len <= nseen; i++)
        if (memcmp(seen + i, text, len) == 0) return (int)(i + len);
    return -1;
}

static void expect(const char *text, size_t len)
{
    double end = now_ms() + WAIT_MS;
    int at;
    while ((at = contains(text, len)) < 0) {
        char msg[600];
        if (now_ms() > end || !pump(100)) {
            snprintf(msg, sizeof msg, "timed out waiting for \"%.*s\"", (int)len, text);
            die(124, msg);
        }
    }
    memmove(seen, seen + at, nseen - (size_t)at);
    nseen -= (size_t)at;
}

static size_t unescape(char *s)
{
    char *o = s, *p = s;
    while (*p) {
        if (*p != '\\' || !p[1]) {
            *o++ = *p++;
            continue;
        }
        p++;
        switch (*p) {
        case 'n': *o++ = '\n'; p++; break;
        case 'r': *o++ = '\r'; p++; break;
        case 't': *o++ = '\t'; p++; break;
        case 'e': *o++ = 27; p++; break;
        case 'x': {
            char hex[3] = {0, 0, 0};
            int k;
            for (p++, k = 0; k < 2 && isxdigit((unsigned char)*p); k++) hex[k] = *p++;
            *o++ = (char)strtol(hex, NULL, 16);
            break;
        }
        default: *o++ = *p++; break;
        }
    }
    *o = '\0';
    return (size_t)(o - s);
}

static void send_text(const char *text, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++) {   /* byte by byte, as typed */
        if (write(master, text + i, 1) != 1) die(125, "cannot write to the terminal");
        pump(5);
    }
}

static void let_run(double seconds)
{
    double end = now_ms() + seconds * 1e3;
    while (now_ms() < end)
        if (!pump(20)) break;
}

static int wait_exit(void)
{
    double end = now_ms() + WAIT_MS;
    int status;
    for (;;) {
        pid_t r = waitpid(child, &status, WNOHANG);
        if (r == child) break;
        if (now_ms() > end) die(124, "timed out waiting for the program to exit");
        if (!pump(50)) usleep(20000);
    }
    while (pump(50))
        ;
    child = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static void start(char **argv)
{
    struct winsize ws = {24, 80, 0, 0};
    char *slave;
    master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || !(slave = ptsname(master)))
        die(125, "cannot open a pseudo-terminal");
    ioctl(master, TIOCSWINSZ, &ws);
    child = fork();
    if (child < 0) die(125, "cannot fork");
    if (child == 0) {
        int fd;
        setsid();
        fd = open(slave, O_RDWR);
        if (fd < 0) _exit(125);
        ioctl(fd, TIOCSCTTY, 0);
        dup2(fd, 0), dup2(fd, 1), dup2(fd, 2);
        if (fd > 2) close(fd);
        close(master);
        execvp(argv[0], argv);
        _exit(127);
    }
}

int main(int argc, char **argv)
{
    char line[8192];
    if (argc < 3) die(125, "usage: ptydrive TRANSCRIPT PROGRAM [ARG...] < SCRIPT");
    transcript = fopen(argv[1], "w");
    if (!transcript) die(125, "cannot write the transcript");
    start(argv + 2);
    while (fgets(line, sizeof line, stdin)) {
        size_t len = strcspn(line, "\n");
        line[len] = '\0';
        if (strncmp(line, "send ", 5) == 0) send_text(line + 5, unescape(line + 5));
        else if (strncmp(line, "expect ", 7) == 0) expect(line + 7, unescape(line + 7));
        else if (strncmp(line, "sleep ", 6) == 0) let_run(atof(line + 6));
        else if (line[0] && line[0] != '#') die(125, "bad script line");
    }
    {
        int status = wait_exit();
        fclose(transcript);
        return status;
    }
}
