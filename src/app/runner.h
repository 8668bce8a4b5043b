/* The lesson runner without a terminal: pages applied to the live app,
 * goals checked each frame and latched, questions answered, hints, page
 * turns, the text pane, and progress saved per user. */
#ifndef SW_APP_RUNNER_H
#define SW_APP_RUNNER_H

#include "app/app.h"
#include "app/progress.h"
#include "app/side.h"
#include "lesson/lesson.h"

#define SW_RUNNER_LINES 160
#define SW_RUNNER_COLS 400

typedef struct sw_runner {
    sw_lesson lesson;
    char file[256];            /* the lesson's file name, the key for progress */
    int page;
    int done;                  /* pages completed so far (saved) */
    unsigned char complete[SW_LESSON_MAX_PAGES];
    unsigned char answered[SW_LESSON_MAX_PAGES];
    unsigned char before[SW_LESSON_MAX_PAGES]; /* completed in an earlier session: its goals
                                                  start fresh, but n may skip it */
    const char *feedback;      /* last answer's feedback */
    int feedback_ok;
    int hint;                  /* 1: show the hint of the first goal not met */
    int hint_scroll;           /* 1: the hint was just asked for: scroll the pane to it */
    int finished;              /* the last page is complete */
    int scroll;                /* first line of the text pane shown */
    int wide;                  /* 1: the text takes the whole width (o: the reading mode) */
    int step;                  /* lines Up and Down move (the composer sets it; 0: 3) */
    char text[SW_RUNNER_LINES][SW_RUNNER_COLS];
    char block[SW_RUNNER_LINES][SW_RUNNER_COLS]; /* scratch: a verbatim block's lines */
    const char *lines[SW_RUNNER_LINES];
    sw_side_kind kinds[SW_RUNNER_LINES];
    sw_side side;
    char save_error[SW_ERRLEN + 32]; /* why progress was not saved ("" when it was) */
} sw_runner;

/* Load the lesson at path and build the app from its first page (or page
 * `page`, clipped; -1: resume from saved progress). 0 or a status with err. */
int sw_runner_start(sw_runner *r, sw_app *a, const char *path, int page, char *err, size_t errlen);
void sw_runner_free(sw_runner *r);
/* Go to page i: apply its settings and locks. */
void sw_runner_enter(sw_runner *r, sw_app *a, int page);
/* What the app shows, as the goals see it. */
void sw_runner_obs(sw_app *a, sw_lesson_obs *obs);
/* Check the page's goals (latched once met); 1 when it just became complete. */
int sw_runner_update(sw_runner *r, sw_app *a);
/* Lesson keys (page turns, hints, answers); 1 when the key was the lesson's. */
int sw_runner_key(sw_runner *r, sw_app *a, int key);
/* The text pane for a terminal `cols` wide. */
const sw_side *sw_runner_side(sw_runner *r, sw_app *a, int cols);

#endif
