/* The claims test's rows for the stage view's page (lesson 6, "Inside one
 * step"): how many slopes a step takes, read from the step the view
 * records on the page as set up, and the key the page names. */
#include "app/stages.h"
#include "claims.h"

#define PAGE "Inside one step"

/* Stages the view records on the page under method (NULL: the page's). */
static double page_stages(const char *method)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L6, PAGE);
    if (method)
        ck_assert_int_eq(sw_app_set_method(&a, sw_integrator_find(method)), SW_OK);
    cl_act(&a, SW_ACT_STAGES, 1);
    ck_assert_msg(a.stages_open, "the stage view did not open: %s", a.stages_why);
    double n = sw_app_stages(&a)->n;
    cl_page_free(&r, &a);
    return n;
}

static double rk4_stages(void) { return page_stages(NULL); }
static double mid_stages(void) { return page_stages("midpoint"); }
static double key_mid(void) { return cl_key_of("midpoint"); }
static double key_euler(void) { return cl_key_of("euler"); }

const claim sw_claims_s[] = {
    { L6, "One RK4 step takes {four} slopes.", rk4_stages, EXACT, 0, R_COUNT, NULL },
    { L6, "and k again: it takes {two}.", mid_stages, EXACT, 0, R_COUNT, NULL },
    { L6, "Press {3} for midpoint and k again", key_mid, EXACT, 0, "the key that picks the method", NULL },
    { L6, "Euler (press {1}) does not.", key_euler, EXACT, 0, "the key that picks the method", NULL },
};
const size_t sw_claims_s_n = sizeof sw_claims_s / sizeof sw_claims_s[0];
