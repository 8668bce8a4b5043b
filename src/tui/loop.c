/* The live loop shared by `play` and the lesson runner: fixed-Δt
 * simulation decoupled from the frame rate (the app's clock), keys, one
 * composed frame painted per tick. Ends on q, a signal (sw_signal_caught),
 * a terminal that went away (counted as SIGHUP) or an error; the terminal
 * is restored before it returns. */
#include "tui/loop.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stepwise/base.h"
#include "tui/term.h"
#include "util/clock.h"
#include "util/signals.h"

/* Steps for one sim per frame: what fits in about 10 ms at the measured
 * cost per step (capacity: steps per second of stepping time). */
static long step_budget(const sw_app *a, double capacity)
{
    double b = (capacity > 0 ? capacity : 2000) * 0.010 / a->nsims;
    return b < 1 ? 1 : b > 1e6 ? 1000000 : (long)b;
}

/* Braille dots are characters only a UTF-8 terminal shows: elsewhere the
 * picture stays ASCII, with a note saying why. */
static void braille_needs_utf8(sw_app *a)
{
    if (a->braille && !sw_term_utf8()) {
        a->braille = 0;
        snprintf(a->message, sizeof a->message, "Braille needs a UTF-8 locale (e.g. LANG=C.UTF-8); "
                 "drawing with ASCII");
    }
}

/* The screen as it stands, painted now. */
static void paint(sw_app *a, const sw_play_hooks *hooks, sw_frame *f, sw_screen *scr)
{
    const sw_side *side = hooks && hooks->side ? hooks->side(hooks->ctx, a, scr->cols) : NULL;
    sw_frame_compose(f, a, side, scr);
    sw_term_paint(scr);
}

/* One key to the hooks (the lesson) or the app; the picture's trails and
 * followed view are forgotten when the run went back or started again
 * (a reset, a rewind, a page or scene of its own: the app's epoch). A key
 * that may work for a second or two says what it does first, so the
 * screen does not look frozen. */
static void take_key(sw_app *a, const sw_play_hooks *hooks, sw_frame *f, sw_screen *scr, int key)
{
    long steps_before = a->sims[0].steps;
    unsigned epoch = a->epoch;
    const char *notice = scr->cols > 0 ? sw_app_key_notice(a, key, hooks != NULL) : NULL;
    if (notice) {
        snprintf(a->message, sizeof a->message, "%s", notice);
        paint(a, hooks, f, scr);
    }
    if (!(hooks && hooks->key && hooks->key(hooks->ctx, a, key)))
        sw_app_key(a, key, hooks != NULL);
    if (a->sims[0].steps < steps_before || a->sims[0].t == 0 || a->epoch != epoch)
        sw_frame_forget(f);
}

int sw_tui_play(sw_app *a, const sw_play_hooks *hooks, char *err, size_t errlen)
{
    sw_frame f;
    sw_screen scr = { 0 };
    if (sw_frame_init(&f, err, errlen) != SW_OK)
        return SW_ENOMEM;
    if (sw_term_start(err, errlen) != SW_OK) {
        sw_frame_free(&f);
        return SW_EIO;
    }
    /* Braille and arrows only where the locale can show them */
    f.unicode = sw_term_utf8();
    int cols = 0, rows = 0;
    double last = sw_clock_now(), rate_t = last, busy = 0, capacity = 0;
    long rate_steps = 0, pushed_steps = -1;
    double pushed_t = -1;
    int status = SW_OK;
    /* Test hook: take the error exit after N frames (docs/robustness.md). */
    const char *force = getenv("STEPWISE_FORCE_ERROR");
    long frames_left = force && *force ? atol(force) : -1;
    while (!a->quit && !sw_signal_caught) {
        if (frames_left == 0) {
            snprintf(err, errlen, "forced error after %s frames (STEPWISE_FORCE_ERROR)", force);
            status = SW_EIO;
            break;
        }
        frames_left -= frames_left > 0;
        int c, r;
        sw_term_size(&c, &r);
        if (c != cols || r != rows) {
            sw_screen_free(&scr);
            if (sw_screen_init(&scr, c < 1 ? 1 : c, r < 1 ? 1 : r, err, errlen) != SW_OK) {
                status = SW_ENOMEM;
                break;
            }
            cols = c;
            rows = r;
        }
        double frame_start = sw_clock_now();
        for (int key; (key = sw_term_key(0)) != -1;) {
            if (key == -2)
                continue;
            if (key == SW_TERM_GONE) {
                sw_signals_hangup();
                break;
            }
            take_key(a, hooks, &f, &scr, key);
            if (a->quit)
                break;
        }
        double now = sw_clock_now();
        long before = a->sims[0].steps;
        sw_app_advance(a, fmin(now - last, 0.1), step_budget(a, capacity));
        last = now;
        busy += sw_clock_now() - now;
        rate_steps += a->sims[0].steps - before;
        if (now - rate_t >= 0.5) {
            a->steps_per_sec = rate_steps / (now - rate_t);
            if (rate_steps > 0 && busy > 0)
                capacity = rate_steps / busy;
            else if (capacity > 0)
                capacity *= 2; /* nothing measured: let the budget grow */
            rate_steps = 0;
            busy = 0;
            rate_t = now;
        }
        braille_needs_utf8(a);
        /* trails age by frames: a paused run pushes nothing, so they stay */
        if (a->sims[0].steps != pushed_steps || a->sims[0].t != pushed_t)
            sw_frame_push_trails(&f, a);
        pushed_steps = a->sims[0].steps;
        pushed_t = a->sims[0].t;
        paint(a, hooks, &f, &scr);
        /* About 60 frames per second; when paused, wait for a key instead of spinning. */
        int wait = a->paused ? 250 : (int)fmax(1.0, 1000.0 / 60 - 1000.0 * (sw_clock_now() - frame_start));
        int key = sw_term_key(wait);
        if (key == SW_TERM_GONE)
            sw_signals_hangup();
        if (key >= 0)
            take_key(a, hooks, &f, &scr, key);
    }
    sw_term_stop(); /* first, so every message below lands on a sane terminal */
    sw_app_record_stop(a); /* a signal, q or an error: the trace is written whole or not at all */
    sw_screen_free(&scr);
    sw_frame_free(&f);
    return status;
}
