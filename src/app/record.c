/* Recording what is on screen as a trace. Recording restarts the main sim at
 * t = 0 and stops when its method, dt or parameters change, so the trace
 * describes one run. On stop the run is replayed headlessly through the
 * same trace writer `stepwise record` uses: sims are deterministic, so the
 * file equals the screen bit for bit, its metadata names the exact number
 * of steps, and nothing appears under the real name until it is complete.
 * app.c restarts the sims and calls down here, never the other way. */
#include "app/app.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "trace/trace.h"
#include "stepwise/base.h"

static int replay(sw_app *a, long steps, char *err, size_t errlen)
{
    sw_sim s;
    sw_trace_writer w;
    const sw_sim *live = &a->sims[0];
    /* a run stopped at the stop time had its last step cut to land there:
     * the trace's until rule cuts it the same way */
    int at_stop = a->until > 0 && live->t == a->until && !live->blown;
    sw_trace_spec spec = { .steps = at_stop ? 0 : steps, .until = at_stop ? a->until : 0, .every = 1 };
    if (sw_sim_init(&s, a->scene, a->p, live->method, live->dt, err, errlen) != SW_OK)
        return SW_EINVAL;
    sw_sim_set_tolerances(&s, live->rtol, live->atol);
    if (sw_sim_set_events(&s, live->events, err, errlen) != SW_OK) {
        sw_sim_free(&s);
        return SW_ENOMEM;
    }
    int rc = sw_trace_open(&w, a->record_path, err, errlen);
    if (rc == SW_OK)
        rc = sw_trace_begin(&w, &s, &spec, err, errlen);
    while (rc == SW_OK && !sw_trace_done(&s, &spec)) {
        rc = sw_trace_step(&s, &spec, err, errlen);
        if (rc == SW_OK)
            rc = sw_trace_observe(&w, &s, err, errlen);
    }
    if (rc == SW_OK && memcmp(s.sys.y, live->sys.y, (size_t)s.sys.ode->dim * sizeof *s.sys.y) != 0 &&
        !(s.blown && live->blown)) {
        snprintf(err, errlen, "the replay did not reproduce the screen (is a plugin not deterministic?)");
        rc = SW_EINVAL;
    }
    if (rc == SW_OK)
        rc = sw_trace_commit(&w, &s, err, errlen);
    else
        sw_trace_abort(&w);
    sw_sim_free(&s);
    return rc;
}

/* Where a relative path lands, said with it: " in DIR" (the directory
 * stepwise was started in, where a student's shell runs stepwise check),
 * or nothing for an absolute path or an unknown directory. */
static void where(const char *path, char *out, size_t len)
{
    char dir[512];
    out[0] = '\0';
    if (path[0] != '/' && getcwd(dir, sizeof dir))
        snprintf(out, len, " in %.160s (the directory stepwise started in)", dir);
}

void sw_app_record_stop(sw_app *a)
{
    if (!a->record_path[0])
        return;
    char err[SW_ERRLEN];
    long steps = a->sims[0].blown ? a->sims[0].blow_step : a->sims[0].steps;
    if (steps < 1)
        snprintf(a->message, sizeof a->message, "recording stopped before the first step: nothing written");
    else if (replay(a, steps, err, sizeof err) != SW_OK)
        snprintf(a->message, sizeof a->message, "recording failed: %s", err);
    else {
        char in[208]; /* where()'s longest: " in " + 160 + 37 */
        where(a->record_path, in, sizeof in);
        snprintf(a->message, sizeof a->message, "recorded %ld steps to %.100s%s; grade it: stepwise check %.100s",
                 steps, a->record_path, in, a->record_path);
        a->recorded = 1;
    }
    a->record_path[0] = '\0';
}

void sw_app_record_begin(sw_app *a, const char *path)
{
    char stamp[32], name[sizeof a->record_path];
    if (!path) {
        time_t now = time(NULL);
        struct tm tmv;
        localtime_r(&now, &tmv);
        strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tmv);
        snprintf(name, sizeof name, "stepwise-%s-%s.trace", a->scene->name, stamp);
        path = name;
    }
    snprintf(a->record_path, sizeof a->record_path, "%s", path);
    a->record_method = a->sims[0].method;
    a->record_dt = a->dt;
    char in[208];
    where(a->record_path, in, sizeof in);
    snprintf(a->message, sizeof a->message, "recording from t = 0 to %.200s%s; R stops and writes it", a->record_path,
             in);
}
