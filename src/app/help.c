/* help.c - `lamina help`, `lamina help CMD` and `lamina CMD ... --help`: one
 * table of the commands, so the overview and each command's own help never
 * disagree. */
#include <stdio.h>
#include <string.h>

#include "app.h"

typedef struct command_help {
    const char *name;       /* "run", "bench engine", ... */
    const char *usage;      /* the synopsis, continuation lines indented */
    const char *what;       /* what it does, and where it is documented */
} command_help;

static const command_help commands[] = {
    {"run",
     "lamina run SCRIPT.lua [--set name=value ...] [--backend cairo|osmesa|egl|gl]\n"
     "           [--threads N] [--report FILE] [--out-root DIR] [--lua-mem MB]\n"
     "           [--memory MB] [--restart CHECKPOINT] [--quiet]",
     "run a scenario; its frames and files go where it says, under the working\n"
     "directory or --out-root DIR; --report FILE also writes lamina.report values\n"
     "as JSON; --lua-mem MB caps the script's Lua memory (default 1024);\n"
     "--memory MB caps the engine, the pictures and Lua together (default 4096,\n"
     "or LAMINA_MEMORY_MB);\n"
     "--restart continues a run from a sim:checkpoint file (docs/api.md)"},
    {"diff",
     "lamina diff EXPECTED.png ACTUAL.png [--out DIFF.png] [--threshold T]\n"
     "            [--max-pixels N] [--max-window N] [--hard-limit L] [--quiet]",
     "compare two images: 0 same, 1 different, 2 error (docs/gallery.md)"},
    {"gallery",
     "lamina gallery [--only PATTERN] [--force] [--check] [--compare]\n"
     "               [--update-baselines] [--scripts DIR] [--gallery DIR]\n"
     "               [--baselines DIR] [--work DIR] [--set name=value] [--quiet]\n"
     "               [--timeout S] [--jobs N]",
     "render scripts/paper/*.lua into gallery/; --timeout is each figure's time\n"
     "limit, default 1800 s; --jobs N figures at once, the costliest first (default:\n"
     "the cores online; docs/gallery.md)"},
    {"repl",
     "lamina repl [SCRIPT.lua] [--set name=value ...] [--quiet]",
     "a Lua prompt over the script's simulation, paused before its first sim:run\n"
     "(docs/workbench.md)"},
    {"watch",
     "lamina watch SCRIPT.lua [--steps N] [--set ...] [--max-runs N | --once]\n"
     "             [--interval S] [--log FILE] [--quiet]",
     "run again each time the script changes (docs/workbench.md)"},
    {"sweep",
     "lamina sweep SCRIPT.lua --set name=v1,v2,... [--set ...] [--jobs N]\n"
     "             [--out DIR] [--emit-jobs | --slurm FILE] [--quiet]\n"
     "lamina sweep --job FOLDER SCRIPT.lua [--set name=value ...]\n"
     "lamina sweep --collect DIR",
     "one run per combination and a summary table; --emit-jobs prints the runs'\n"
     "commands (GNU parallel), --slurm FILE writes a Slurm job array,\n"
     "--collect summarises their folders (docs/workbench.md)"},
    {"serve",
     "lamina serve SCRIPT.lua [--port N] [--host ADDR] [--allow-remote]\n"
     "             [--set name=value ...] [--paused] [--keep] [--quiet]",
     "run a scenario and watch it in a browser: its latest frames, recorders'\n"
     "plots, progress; pause, step, resume, change lamina.param values and live\n"
     "settings. Port 8035 (0: a free one, printed); 127.0.0.1 unless --host and\n"
     "--allow-remote; --paused waits after the first step; --keep serves after\n"
     "the run's end until Ctrl-C (docs/workbench.md)"},
    {"animate",
     "lamina animate FOLDER|FRAME.png... [--out FILE.apng|FILE.mp4] [--fps N]\n"
     "               [--loop N] [--pattern GLOB] [--quiet]",
     "a run's frames as one animation (APNG; MP4 through ffmpeg when installed);\n"
     "--pattern takes a folder's frames whose names match; frames of another size\n"
     "than the first are left out with a warning (docs/rendering.md)"},
    {"bench render",
     "lamina bench render [--width W] [--height H] [--runs N] [--counts N,...]\n"
     "                    [--backend cairo|osmesa|egl|gl|all]",
     "milliseconds per frame for each renderer (README, \"Rendering and benchmarks\")"},
    {"bench render3d",
     "lamina bench render3d [--runs N] [--counts N,...] [--backend cairo|osmesa|egl|all]",
     "milliseconds per 3D frame, wall and CPU, for OSMesa and EGL (docs/performance.md,\n"
     "\"3D frames\")"},
    {"bench engine",
     "lamina bench engine [--dim 2|3] [--sizes N,...] [--work PARTICLE_STEPS]\n"
     "                    [--threads N] [--basis linear|gimp|bspline2]",
     "particle-steps per second of the step (README, \"Engine performance\");\n"
     "--dim 3 (also `lamina bench --dim 3`): the 3D engine's block, trilinear and\n"
     "B-spline, and its bytes a particle (docs/performance.md, \"3D\"); there\n"
     "--simd sse2 holds the trilinear scatters to two lanes (default best: AVX-512F\n"
     "where the processor has it, the same bits)"},
    {"bench threads",
     "lamina bench threads [--sizes N,...] [--steps N] [--pairs N] [--threads N]\n"
     "                     [--idle | --loaded]",
     "1 thread against 2, idle and beside a busy loop (docs/performance.md, \"Threads\")"},
    {"bench roofline",
     "lamina bench roofline [--particles N] [--work PARTICLE_STEPS]\n"
     "                      [--basis linear|gimp|bspline2|all] [--repeats N]\n"
     "                      [--triad-mb MB]",
     "bytes per particle-step (counted), one core's triad GB/s and the fraction\n"
     "of it each step reaches (docs/performance.md, \"Roofline\")"},
    {"help", "lamina help [COMMAND]", "this text, or one command's"},
};
#define NCOMMANDS (sizeof commands / sizeof commands[0])

/* Each line of text, after the indent. */
static void lines(FILE *out, const char *indent, const char *s)
{
    while (*s) {
        size_t n = strcspn(s, "\n");
        fprintf(out, "%s%.*s\n", indent, (int)n, s);
        s += n + (s[n] == '\n');
    }
}

static void print_one(FILE *out, const command_help *c)
{
    lines(out, "  ", c->usage);
    lines(out, "        ", c->what);   /* the description under it */
}

void app_usage(FILE *out)
{
    fprintf(out, "lamina %s - membranes, gas and their interaction with the material "
            "point method\n\nusage:\n", LAMINA_VERSION);
    for (size_t k = 0; k < NCOMMANDS; k++) print_one(out, &commands[k]);
    fprintf(out, "  lamina --version\n        the version\n\n"
            "Every command answers --help. Exit status: 0 success, 1 the simulation\n"
            "failed (instability, a particle left the domain), 2 the script or the\n"
            "command line is wrong. The Lua API is described in docs/api.md.\n");
}

int app_command_help(FILE *out, const char *cmd, const char *sub)
{
    char name[64];
    if (sub && strcmp(cmd, "bench") == 0 && sub[0] != '-')
        snprintf(name, sizeof name, "%s %s", cmd, sub);
    else
        snprintf(name, sizeof name, "%s", cmd);
    int found = 0;
    for (size_t k = 0; k < NCOMMANDS; k++) {
        /* "bench" alone: both benchmarks */
        size_t n = strlen(name);
        if (strcmp(commands[k].name, name) == 0 ||
            (strncmp(commands[k].name, name, n) == 0 && commands[k].name[n] == ' ')) {
            if (!found) fprintf(out, "usage:\n");
            print_one(out, &commands[k]);
            found = 1;
        }
    }
    if (!found) {
        fprintf(stderr, "lamina help: unknown command '%s' (try 'lamina help')\n", name);
        return 2;
    }
    return 0;
}

int app_wants_help(int argc, char **argv)
{
    for (int i = 0; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) return 1;
    return 0;
}
