/* Lessons: a plain-text file a teacher writes (lessons/README.md is the
 * authoring guide) parsed into pages of prose, settings, goals and questions.
 * Pure: no terminal, no printing. Everything in a file is checked against the
 * real catalog at parse time, so a lesson that loads can be run. */
#ifndef SW_LESSON_LESSON_H
#define SW_LESSON_LESSON_H

#include <stddef.h>

#include "lesson/controls.h"
#include "stepwise/base.h"
#include "stepwise/integrator.h"
#include "stepwise/scene.h"
#include "stepwise/sim.h"

/* Bounds, documented in lessons/README.md; anything past them is a parse
 * error naming the bound, never a truncation. */
#define SW_LESSON_MAX_BYTES (256 * 1024) /* a lesson file */
#define SW_LESSON_MAX_LINE 1000          /* bytes in one line, newline excluded */
#define SW_LESSON_MAX_TITLE 80           /* characters in a lesson or page title */
#define SW_LESSON_MAX_PAGES 64
#define SW_LESSON_MAX_PROSE 6000         /* bytes of prose on one page */
#define SW_LESSON_MAX_BLOCKS 64          /* paragraphs and verbatim blocks on one page */
#define SW_LESSON_MAX_GOALS 8            /* goals on one page */
#define SW_LESSON_MAX_ANSWERS 6          /* answers a) .. f) to one question */
#define SW_LESSON_MAX_COMPARE 2          /* methods run beside the main one */
#define SW_LESSON_MAX_NAMES 4            /* names in one `integrator in ...` goal */
#define SW_LESSON_MAX_FILES 256          /* lessons in one directory */
#define SW_LESSON_ERRLEN 512             /* a message buffer that holds every parse error whole */

/* ---- observation: what the live app tells the lesson each frame ----------- */

typedef struct sw_lesson_obs {
    const char *scene;        /* scene name */
    const char *integrator;   /* the main sim's method name */
    double dt;                /* the main sim's step */
    double t;                 /* simulated time */
    long steps, evals;        /* steps taken, derivative evaluations */
    int blown;                /* 1 once the main sim has blown up */
    double energy_drift;      /* (E - E0)/|E0| in percent; NaN when the scene has no energy */
    double error;             /* largest state error against the exact solution or the
                               * reference run, now; NaN when there is neither */
    double drift;             /* the scene's invariant drift now; NaN when it has none */
    int compare, ghost, paused;
    double speed;             /* simulated seconds per wall second */
    /* Of the two most recent errors measured at the scene's report time
     * (sw_scene.duration) with different Δt: error at the larger Δt divided by
     * error at the smaller, so ≈ 2^p for a method of order p when Δt was halved
     * or doubled. NaN until two such measurements exist. */
    double error_ratio;
    long accepted, rejected;  /* rk45 accepted and rejected steps (0 for other methods) */
    int nparams;              /* current scene's parameters, in its order */
    const char *param_name[SW_MAX_PARAMS];
    double param_value[SW_MAX_PARAMS];
    int recorded;             /* 1 once a trace recording has been made (R) */
    int phase, region;        /* the phase view (v) or the stability-region view (s) is shown */
} sw_lesson_obs;

/* Everything unknown: NaN numbers, zero counters, NULL names. */
void sw_lesson_obs_init(sw_lesson_obs *obs);
/* Fill what a sim knows: scene, integrator, dt, t, steps, evals, blown,
 * energy drift, invariant drift, rk45 counts and the parameters. The app
 * fills the rest (error, error_ratio, compare, ghost, paused, speed,
 * recorded). The obs points into the sim: refill after the sim changes. */
void sw_lesson_obs_from_sim(sw_lesson_obs *obs, const sw_sim *sim);

/* ---- goals ---------------------------------------------------------------- */

typedef enum sw_lesson_var {
    /* names */
    SW_LV_SCENE, SW_LV_INTEGRATOR,
    /* numbers */
    SW_LV_DT, SW_LV_T, SW_LV_STEPS, SW_LV_EVALS, SW_LV_SPEED, SW_LV_ENERGY_DRIFT,
    SW_LV_ERROR, SW_LV_DRIFT, SW_LV_ERROR_RATIO, SW_LV_ACCEPTED, SW_LV_REJECTED, SW_LV_PARAM,
    /* yes/no */
    SW_LV_BLOWN, SW_LV_COMPARE, SW_LV_GHOST, SW_LV_PAUSED, SW_LV_RECORDED, SW_LV_PHASE, SW_LV_REGION,
    SW_LV_COUNT
} sw_lesson_var;

typedef enum sw_lesson_op {
    SW_LOP_EQ, SW_LOP_NE, SW_LOP_LT, SW_LOP_LE, SW_LOP_GT, SW_LOP_GE,
    SW_LOP_NEAR,  /* |value - target| <= tol */
    SW_LOP_IN     /* a name among names[] */
} sw_lesson_op;

/* A predicate on the observation. Names: op EQ, NE or IN over names[].
 * Numbers: any comparison; NaN never meets a goal. Yes/no: op EQ, value 0/1. */
typedef struct sw_lesson_goal {
    sw_lesson_var var;
    sw_lesson_op op;
    int absolute;             /* compare |value| (drifts) */
    double value;             /* the number compared with, or 0/1 */
    double tol;               /* SW_LOP_NEAR: allowed distance */
    const char *param;        /* SW_LV_PARAM: the parameter's name */
    const char *names[SW_LESSON_MAX_NAMES];
    int nnames;
    const char *hint;         /* shown on request; every goal has one */
    int line;                 /* where it was written, for messages */
} sw_lesson_goal;

/* 1 when obs meets g, else 0. == and <=, >= allow a relative slack of 1e-9
 * so that a Δt reached by doubling equals the number the teacher wrote. */
int sw_lesson_goal_met(const sw_lesson_goal *g, const sw_lesson_obs *obs);
/* Render g as short text for the ✓/✗ list ("integrator is rk4", "dt >= 0.2",
 * "|energy drift| < 1 %"); always NUL-terminated, truncated to len. */
void sw_lesson_goal_text(const sw_lesson_goal *g, char *buf, size_t len);
/* The goal vocabulary: name of a variable as written in a file, and lookup
 * (accepts the aliases "Δt" and "time"); -1 when unknown. */
const char *sw_lesson_var_name(sw_lesson_var v);
int sw_lesson_var_find(const char *name);

/* ---- locks: controls a page can take from the student ----------------------
 * The lock groups (SW_LOCK_*) and their names come from the one list of
 * controls in lesson/controls.h. */

/* ---- pages and lessons ----------------------------------------------------- */

/* What a page's @view shows (the app's views, in its order). */
enum { SW_LESSON_VIEW_SCENE = 0, SW_LESSON_VIEW_PHASE = 1, SW_LESSON_VIEW_REGION = 2 };
/* @speed's range (the app's). */
#define SW_LESSON_SPEED_MIN (1.0 / 64)
#define SW_LESSON_SPEED_MAX 1024.0
/* @view box='s largest coordinate, in the scene's units. */
#define SW_LESSON_BOX_MAX 1e6
/* @until's latest stop time, in seconds (the app's). */
#define SW_LESSON_UNTIL_MAX 1e6

typedef struct sw_lesson_block {
    int verbatim;             /* 1: lines shown as written ('\n' between them);
                               * 0: a paragraph the UI wraps to the pane width */
    const char *text;
    int line;
} sw_lesson_block;

typedef struct sw_lesson_choice {
    char letter;              /* 'a', 'b', ... in order */
    const char *text;
    const char *feedback;     /* shown when this answer is chosen */
} sw_lesson_choice;

typedef struct sw_lesson_question {
    const char *text;         /* NULL: the page has no question */
    sw_lesson_choice answers[SW_LESSON_MAX_ANSWERS];
    int nanswers;
    int correct;              /* index into answers */
    const char *hint;         /* may be NULL */
    int line;
} sw_lesson_question;

typedef struct sw_lesson_page {
    const char *title;
    int line;                 /* the `--- title` line */
    const sw_lesson_block *blocks;
    int nblocks;

    /* Settings applied on entering the page. When restart is 1 the runner
     * rebuilds the sim from scene, p, method and dt below and starts it at
     * t = 0; when 0 the sim goes on as the student left it. scene, p, method
     * and dt are always filled: what the page says, else what earlier pages
     * said (a @scene brings the scene's defaults). p has the scene's
     * nparams values, then zeros. */
    int restart;
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    const sw_integrator *method;
    double dt;
    int compare;              /* -1: leave as is; 0 off; 1 on */
    const sw_integrator *compare_with[SW_LESSON_MAX_COMPARE]; /* methods run beside */
    int ncompare_with;        /* 0: the app's own choice */
    int ghost;                /* -1 / 0 / 1 as compare */
    int events;               /* -1: leave as is; SW_EVENTS_STEP or SW_EVENTS_LOCATE (@events) */
    int paused;               /* -1 / 0 / 1: start paused or running */
    double speed;             /* simulated seconds per wall second; 0: leave as is */
    int view;                 /* SW_LESSON_VIEW_*; -1: leave as is */
    int follow;               /* -1 / 0 / 1: camera fixed on the scene or following */
    int lanes;                /* -1 / 0 / 1: compare overlaid or side by side */
    int graph;                /* -1 / 0 / 1: the energy/error graph off or on */
    double zoom;              /* the view's size times this; 0: leave as is */
    double box[4];            /* @view box=X0,Y0,X1,Y1: the world rectangle the camera shows
                               * (metres or the scene's units), when has_box */
    int has_box;              /* 0: leave the camera's rectangle as is */
    double until;             /* @until: the run stops at this time (seconds); 0: no stop time */
    sw_lock_mask locked;      /* SW_LOCK_* in force on this page (carried from earlier pages) */

    sw_lesson_goal goals[SW_LESSON_MAX_GOALS];
    int ngoals;
    sw_lesson_question question;
} sw_lesson_page;

struct sw_lesson_chunk;

typedef struct sw_lesson {
    const char *name;         /* the file name given to the parser, for messages */
    const char *title;
    sw_lesson_page *pages;
    int npages;
    struct sw_lesson_chunk *mem; /* owns every string and array above */
} sw_lesson;

/* Parse len bytes of text (need not be NUL-terminated; may hold any bytes).
 * On success 0 and *out owns its memory (sw_lesson_free). On failure
 * SW_EINVAL with err = "NAME:LINE:COL: what was wrong; expected ..." (or
 * SW_ENOMEM), and *out is empty (safe to free). */
int sw_lesson_parse(const char *name, const char *text, size_t len, sw_lesson *out,
                    char *err, size_t errlen);
/* Read and parse a file of at most SW_LESSON_MAX_BYTES. SW_EIO with
 * "PATH: why" for a missing, unreadable, non-regular or too large file. */
int sw_lesson_load(const char *path, sw_lesson *out, char *err, size_t errlen);
void sw_lesson_free(sw_lesson *lesson);

/* Answer a page's question with a letter (either case). Returns 1 correct,
 * 0 incorrect, with *feedback set to that answer's feedback; SW_EINVAL when
 * the page has no question or no such answer (*feedback then says what the
 * letters are; it points to static or lesson memory). */
int sw_lesson_answer(const sw_lesson_page *page, int letter, const char **feedback);
/* 1 when every goal holds in obs and the question (if any) was answered
 * correctly. The runner latches it: once complete, a page stays complete. */
int sw_lesson_page_complete(const sw_lesson_page *page, const sw_lesson_obs *obs,
                            int answered_correctly);

/* ---- discovery -------------------------------------------------------------- */

typedef struct sw_lesson_entry {
    char *path;               /* DIR/FILE */
    char *file;               /* FILE, e.g. "02-euler.lesson" */
    char *title;              /* the lesson's title, or NULL when it does not load */
    char error[SW_LESSON_ERRLEN]; /* why it does not load ("" when it does) */
    int npages;
} sw_lesson_entry;

/* List the *.lesson files in dir (hidden files skipped) sorted by file name
 * in byte order, parsing each for its title. 0 with *out (count *n, possibly
 * 0), or SW_EIO / SW_ENOMEM / SW_EINVAL (more than SW_LESSON_MAX_FILES). */
int sw_lesson_list(const char *dir, sw_lesson_entry **out, int *n, char *err, size_t errlen);
void sw_lesson_list_free(sw_lesson_entry *entries, int n);

#endif
