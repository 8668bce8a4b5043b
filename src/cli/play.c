/* `stepwise play`: a scene live in the terminal, or N frames as plain text
 * with --ascii (no terminal needed). Both run the same app model and the
 * same composer; only painting differs. */
#include "cli/cli.h"

#include <getopt.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/app.h"
#include "render/screen.h"
#include "tui/loop.h"
#include "util/num.h"
#include "util/signals.h"
#include "util/utf8.h"

/* A live scene whose report time is below this many seconds starts paused. */
#define PLAY_PAUSED_BELOW 3.0

static const char play_help[] =
    "usage: stepwise play SCENE [OPTIONS]\n\n"
    "Runs SCENE live in the terminal; change the integrator and dt while it runs\n"
    "(press ? for the keys).\n\n"
    "options:\n"
    "  -i, --integrator NAME   start with this integrator (stepwise list integrators)\n"
    "      --dt H              step size (default: the scene's)\n"
    "  -s, --set PARAM=VALUE   set a scene parameter (repeatable; see stepwise describe)\n"
    "      --plugin FILE       add a student integrator (.so, or .c built for you) built\n"
    "                          against <stepwise/integrator.h>; it runs jailed, apart\n"
    "      --compare           start with compare on;  --ghost  with the ghost on\n"
    "      --frames N          with --ascii: print N frames (1/60 s each) and exit\n"
    "      --ascii             print frames as plain text instead of opening the terminal UI\n"
    "      --braille           draw with Braille dots\n"
    "      --size COLSxROWS    frame size for --ascii (default 80x24)\n"
    "      --speed X           simulated seconds per wall second (default 1)\n"
    "      --until T           stop the run at t = T seconds exactly (u runs there at once)\n"
    "      --view VIEW         start with this view: scene, phase or region\n"
    "      --lanes             compare side by side;  --follow  the camera follows the particles\n"
    "      --zoom X            the view's size times X (2: zoomed out)\n"
    "      --events MODE       locate: cut steps at contacts and crossings (every method\n"
    "                          keeps its order); step: meet them at step ends (default)\n"
    "  -h, --help              this help\n";

int sw_cli_play(sw_app *a, const sw_play_hooks *hooks)
{
    char err[SW_ERRLEN];
    if (sw_tui_play(a, hooks, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    return sw_signals_status();
}

/* Print `frames` frames of the composed screen as text; a write error
 * (a full disk, a closed pipe) is an error. */
static int ascii_frames(sw_app *a, long frames, int cols, int rows)
{
    sw_frame f;
    sw_screen scr;
    char err[SW_ERRLEN];
    if (sw_frame_init(&f, err, sizeof err) != SW_OK || sw_screen_init(&scr, cols, rows, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    f.unicode = a->braille; /* plain text frames stay ASCII unless Braille was asked for */
    size_t cap = (size_t)cols * (size_t)rows * 4 + (size_t)rows + 1;
    char *text = malloc(cap);
    if (!text)
        return sw_cli_error("out of memory for a %dx%d frame", cols, rows);
    for (long k = 0; k < frames; k++) {
        if (k > 0)
            sw_app_advance(a, 1.0 / 60, 1000000);
        sw_frame_push_trails(&f, a);
        sw_frame_compose(&f, a, NULL, &scr);
        sw_screen_to_text(&scr, text, cap);
        if (k > 0)
            fputc('\n', stdout);
        fputs(text, stdout);
        if (ferror(stdout))
            break;
    }
    free(text);
    sw_screen_free(&scr);
    sw_frame_free(&f);
    return sw_cli_flush_stdout();
}

int sw_cmd_play(int argc, char **argv)
{
    static const struct option opts[] = {
        { "integrator", required_argument, NULL, 'i' }, { "dt", required_argument, NULL, 'd' },
        { "set", required_argument, NULL, 's' },        { "plugin", required_argument, NULL, 'P' },
        { "frames", required_argument, NULL, 'f' },     { "ascii", no_argument, NULL, 'a' },
        { "braille", no_argument, NULL, 'b' },          { "size", required_argument, NULL, 'z' },
        { "speed", required_argument, NULL, 'S' },      { "compare", no_argument, NULL, 'c' },
        { "ghost", no_argument, NULL, 'g' },            { "help", no_argument, NULL, 'h' },
        { "view", required_argument, NULL, 'V' },       { "lanes", no_argument, NULL, 'L' },
        { "follow", no_argument, NULL, 'F' },           { "zoom", required_argument, NULL, 'Z' },
        { "events", required_argument, NULL, 'E' },     { "until", required_argument, NULL, 'U' },
        { NULL, 0, NULL, 0 },
    };
    sw_run_opts o;
    memset(&o, 0, sizeof o);
    const char *method_name = NULL;
    long frames = 0;
    int ascii = 0, braille = 0, compare = 0, ghost = 0, cols = 80, rows = 24;
    double speed = 1, zoom = 1, until = 0;
    int view = SW_VIEW_SCENE, lanes = 0, follow = 0;
    optind = 1;
    opterr = 0;
    for (int c; (c = getopt_long(argc, argv, ":i:s:h", opts, NULL)) != -1;) {
        switch (c) {
        case 'i': method_name = optarg; break;
        case 'd': if (sw_cli_dt("--dt", optarg, &o.dt)) return SW_EXIT_USAGE; break;
        case 's': if (sw_cli_add_set(&o, optarg)) return SW_EXIT_USAGE; break;
        case 'P': if (sw_cli_plugin("--plugin", optarg, NULL)) return SW_EXIT_USAGE; break;
        case 'f': if (sw_cli_long("--frames", optarg, 1, 100000, &frames)) return SW_EXIT_USAGE; break;
        case 'a': ascii = 1; break;
        case 'b': braille = 1; break;
        case 'c': compare = 1; break;
        case 'g': ghost = 1; break;
        case 'S':
            if (sw_cli_positive("--speed", optarg, &speed)) return SW_EXIT_USAGE;
            if (speed < SW_APP_SPEED_MIN || speed > SW_APP_SPEED_MAX)
                return sw_cli_error("--speed %g is outside [%g, %g]", speed, SW_APP_SPEED_MIN, SW_APP_SPEED_MAX);
            break;
        case 'z':
            if (sscanf(optarg, "%dx%d", &cols, &rows) != 2 || cols < SW_MIN_COLS || rows < SW_MIN_ROWS ||
                cols > 1000 || rows > 1000)
                return sw_cli_error("--size '%.40s' is not allowed: give COLSxROWS between %dx%d and 1000x1000",
                                    optarg, SW_MIN_COLS, SW_MIN_ROWS);
            break;
        case 'V':
            if (strcmp(optarg, "scene") == 0) view = SW_VIEW_SCENE;
            else if (strcmp(optarg, "phase") == 0) view = SW_VIEW_PHASE;
            else if (strcmp(optarg, "region") == 0) view = SW_VIEW_REGION;
            else return sw_cli_error("--view '%.40s' is not a view: give scene, phase or region", optarg);
            break;
        case 'L': lanes = 1; break;
        case 'U':
            if (sw_parse_double(optarg, &until) != SW_OK || !(until > 0 && until <= SW_APP_UNTIL_MAX))
                return sw_cli_error("--until '%.40s' is not allowed: give a time in seconds, a number greater "
                                    "than 0 and at most %g", optarg, SW_APP_UNTIL_MAX);
            break;
        case 'E': if (sw_cli_events(optarg, &o.events)) return SW_EXIT_USAGE; break;
        case 'F': follow = 1; break;
        case 'Z':
            if (sw_cli_positive("--zoom", optarg, &zoom)) return SW_EXIT_USAGE;
            if (zoom < 1.0 / 64 || zoom > 4096)
                return sw_cli_error("--zoom %g is outside [1/64, 4096]", zoom);
            break;
        case 'h': fputs(play_help, stdout); return SW_EXIT_OK;
        case ':': return sw_cli_error("%s needs a value; see 'stepwise play --help'", argv[optind - 1]);
        default: return sw_cli_error("play: unknown option '%s'; see 'stepwise play --help'", argv[optind - 1]);
        }
    }
    if (optind != argc - 1)
        return sw_cli_error(optind >= argc ? "play needs a scene; see 'stepwise list scenes'"
                                           : "play takes one scene (got '%s' too)", argv[optind + 1 < argc ? optind + 1 : optind]);
    if (sw_cli_scene(argv[optind], &o.scene) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (method_name && sw_cli_integrator(method_name, &o.method) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (sw_cli_finish_opts(&o) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (frames && !ascii)
        ascii = 1;
    if (!ascii && (!isatty(STDOUT_FILENO) || !isatty(STDIN_FILENO)))
        return sw_cli_error("play needs a terminal; for a trace use 'stepwise record', for text frames "
                            "'stepwise play %s --frames N --ascii'", o.scene->name);
    sw_app a;
    char err[SW_ERRLEN];
    if (sw_app_init(&a, o.scene, o.p, o.method, o.dt, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    a.speed = speed;
    sw_app_set_events(&a, o.events);
    if (compare)
        sw_app_set_compare(&a, 1, NULL, NULL);
    if (ghost)
        sw_app_set_ghost(&a, 1);
    a.braille = braille;
    /* Braille dots are UTF-8 characters: in another locale the frames stay
     * ASCII (the live UI says so on its message line). */
    if (ascii && braille) {
        setlocale(LC_CTYPE, "");
        if (!sw_utf8_locale()) {
            a.braille = 0;
            sw_cli_note("--braille needs a UTF-8 locale (e.g. LANG=C.UTF-8); drawing with ASCII");
        }
    }
    sw_app_set_view(&a, (sw_app_view)view);
    a.lanes = lanes;
    a.follow = follow;
    a.zoom = zoom;
    sw_app_set_until(&a, until);
    if (until > 0)
        snprintf(a.message, sizeof a.message, "the run stops at t = %g (--until); u runs straight there", until);
    if (!ascii && o.scene->duration < PLAY_PAUSED_BELOW && until <= 0) {
        /* a scene that reports this early (a projectile's flight) would be
         * there before the window is drawn and read: it waits for space.
         * The report time is not when the motion ends (the galaxy and the
         * stiff pendulum go on): the message says which it is. */
        a.paused = 1;
        snprintf(a.message, sizeof a.message, "paused: this scene reports at t = %g s; space runs it, [ slows it, "
                 ". steps", o.scene->duration);
    }
    int rc = ascii ? ascii_frames(&a, frames ? frames : 1, cols, rows) : sw_cli_play(&a, NULL);
    sw_app_free(&a);
    return rc;
}
