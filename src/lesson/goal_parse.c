/* The goal grammar: a lexer for one @goal line and a recursive-descent
 * sw_lp_parser into an sw_lesson_goal, checking each name against the catalog and
 * each variable against what the page's scene can measure. */
#include "lesson/parse.h"

#include <stdio.h>
#include <string.h>

#include "util/names.h"
#include "util/num.h"

typedef enum tkind { T_END, T_WORD, T_NUM, T_OP, T_BAR, T_PERCENT, T_LPAREN, T_RPAREN, T_COMMA } tkind;

typedef struct token {
    tkind kind;
    size_t at, len;                  /* bytes in the current line */
    char text[SW_LESSON_NAME_MAX];   /* the word, number, or normalised operator */
} token;

static int word_byte(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.' || c >= 0x80;
}

/* Whether s[i..n) starts with one of the signs ≤ ≥ ≠ (E2 89 A4/A5/A0);
 * returns the operator it stands for, or NULL. */
static const char *unicode_op(const char *s, size_t i, size_t n)
{
    if (i + 2 >= n || (unsigned char)s[i] != 0xE2 || (unsigned char)s[i + 1] != 0x89)
        return NULL;
    unsigned char d = (unsigned char)s[i + 2];
    return d == 0xA4 ? "<=" : d == 0xA5 ? ">=" : d == 0xA0 ? "!=" : NULL;
}

/* Read the token at *pos into tk. */
static int lex(sw_lp_parser *ps, size_t *pos, token *tk)
{
    const char *s = ps->ln;
    size_t i = *pos, n = ps->lnlen;
    while (i < n && sw_lp_blank(s[i]))
        i++;
    memset(tk, 0, sizeof *tk);
    tk->at = i;
    if (i >= n) {
        tk->kind = T_END;
        *pos = i;
        return SW_OK;
    }
    unsigned char c = (unsigned char)s[i];
    size_t j = i;
    const char *op = unicode_op(s, i, n);
    if (op) {
        tk->kind = T_OP;
        strcpy(tk->text, op);
        tk->len = 3;
        *pos = i + 3;
        return SW_OK;
    }
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c >= 0x80) {
        while (j < n && word_byte((unsigned char)s[j]) && !unicode_op(s, j, n))
            j++;
        tk->kind = T_WORD;
    } else if ((c >= '0' && c <= '9') || ((c == '.' || c == '-' || c == '+') && i + 1 < n &&
               (((unsigned char)s[i + 1] >= '0' && (unsigned char)s[i + 1] <= '9') || s[i + 1] == '.'))) {
        j++;
        while (j < n && (word_byte((unsigned char)s[j]) || s[j] == '+' ||
                         (s[j] == '-' && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
            j++;
        tk->kind = T_NUM;
    } else if (strchr("<>=!", (int)c)) {
        /* Take every operator character, so "=>" is reported whole. */
        while (j < n && j - i < 3 && strchr("<>=!", (int)(unsigned char)s[j]))
            j++;
        tk->kind = T_OP;
    } else {
        j++;
        tk->kind = c == '|' ? T_BAR : c == '%' ? T_PERCENT : c == '(' ? T_LPAREN : c == ')' ? T_RPAREN
                 : c == ',' ? T_COMMA : T_END;
        if (tk->kind == T_END) {
            if (c >= 0x20 && c < 0x7F)
                return FAIL(ps, i, "unexpected '%c' in the goal; expected a name, a number or one of "
                            "== != < <= > >= |", c);
            return FAIL(ps, i, "unexpected character in the goal; expected a name, a number or one of "
                        "== != < <= > >= |");
        }
    }
    tk->len = j - i;
    if (sw_lp_field_word(ps, i, tk->len, tk->text) != SW_OK)
        return ps->status;
    if (tk->kind == T_OP) {
        static const char *const known[] = { "==", "!=", "<", "<=", ">", ">=", "=", "!" };
        int ok = 0;
        for (int k = 0; k < 8; k++)
            ok |= strcmp(tk->text, known[k]) == 0;
        if (!ok)
            return FAIL(ps, i, "'%s' is not an operator; expected one of == != < <= > >=", tk->text);
        if (strcmp(tk->text, "=") == 0)
            strcpy(tk->text, "==");
    }
    *pos = j;
    return SW_OK;
}

static const char *var_list =
    "integrator, scene, dt, t, steps, evals, speed, energy_drift, error, drift, error_ratio, "
    "accepted, rejected, param NAME, blown, compare, ghost, paused, recorded, phase, region";

static int var_is_name(int v) { return v == SW_LV_SCENE || v == SW_LV_INTEGRATOR; }
static int var_is_bool(int v) { return v >= SW_LV_BLOWN && v < SW_LV_COUNT; }

static const char *var_name_at(const void *ctx, int i)
{
    (void)ctx;
    return sw_lesson_var_name((sw_lesson_var)i);
}

static int goal_var(sw_lp_parser *ps, const token *tk, int *var)
{
    if (tk->kind != T_WORD)
        return FAIL(ps, tk->at, "expected a goal variable (%s)", var_list);
    *var = sw_lesson_var_find(tk->text);
    if (*var < 0) {
        char near[80];
        return FAIL(ps, tk->at, "unknown goal variable '%s'%s; expected one of %s", tk->text,
                    sw_lp_suggest("", tk->text, var_name_at, NULL, SW_LV_COUNT, near, sizeof near), var_list);
    }
    return SW_OK;
}

static int goal_number(sw_lp_parser *ps, size_t *pos, int percent_ok, double *out)
{
    token tk;
    if (lex(ps, pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_END)
        return FAIL(ps, tk.at, "the goal ends too soon; expected a number");
    if (tk.kind != T_NUM || sw_parse_double(tk.text, out) != SW_OK)
        return FAIL(ps, tk.at, "expected a number here, not '%s'", tk.text);
    size_t save = *pos;
    if (lex(ps, pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_PERCENT) {
        if (!percent_ok)
            return FAIL(ps, tk.at, "'%%' only goes with energy_drift (a percentage); expected a plain number");
    } else {
        *pos = save;
    }
    return SW_OK;
}

/* Whether the scene in effect can ever give this variable a value. */
static int var_available(sw_lp_parser *ps, const token *tk, int var)
{
    const sw_scene *sc = ps->scene;
    const char *missing = NULL;
    if (var == SW_LV_ENERGY_DRIFT && !sc->energy)
        missing = "energy";
    else if ((var == SW_LV_ERROR || var == SW_LV_ERROR_RATIO) && !sc->exact && !sc->reference)
        missing = "exact solution or reference run to measure error against";
    else if (var == SW_LV_DRIFT && !sc->drift)
        missing = "invariant";
    if (missing)
        return FAIL(ps, tk->at, "scene '%s' has no %s, so a goal on %s can never be met; expected a "
                    "goal this scene can meet", sc->name, missing, tk->text);
    return SW_OK;
}

/* Check a method name in a goal: it must exist and be able to step the page's system. */
static int goal_method(sw_lp_parser *ps, const token *tk, const sw_integrator **out);

static int goal_bool_value(sw_lp_parser *ps, const token *tk, double *out)
{
    static const char *const yes[] = { "on", "yes", "true", "1" }, *const no[] = { "off", "no", "false", "0" };
    for (int i = 0; i < 4; i++) {
        if (strcmp(tk->text, yes[i]) == 0) {
            *out = 1;
            return SW_OK;
        }
        if (strcmp(tk->text, no[i]) == 0) {
            *out = 0;
            return SW_OK;
        }
    }
    return FAIL(ps, tk->at, "expected on/off (or yes/no) here, not '%s'", tk->kind == T_END ? "" : tk->text);
}

/* goal := ('not'|'!') BOOL | BOOL [op VALUE] | NAMEVAR ('=='|'!='|'is' ['not']) NAME
 *       | NAMEVAR 'in' NAME [','] NAME ... | TERM op NUMBER ['%']
 *       | TERM 'near' NUMBER ['%'] 'within' NUMBER ['%']
 * TERM := VAR | '|' VAR '|' | 'abs' '(' VAR ')'   VAR := NUMVAR | 'param' NAME */
static int parse_goal(sw_lp_parser *ps, size_t pos, sw_lesson_goal *g)
{
    token tk;
    memset(g, 0, sizeof *g);
    g->line = ps->line;
    if (lex(ps, &pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_END)
        return FAIL(ps, ps->lnlen, "@goal needs a condition; expected e.g. 'integrator == rk4', "
                    "'dt >= 0.2', '|energy_drift| < 1', 'blown'");
    int negate = 0, var = -1, close = T_END;
    if ((tk.kind == T_WORD && strcmp(tk.text, "not") == 0) || (tk.kind == T_OP && strcmp(tk.text, "!") == 0)) {
        negate = 1;
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    } else if (tk.kind == T_BAR || (tk.kind == T_WORD && strcmp(tk.text, "abs") == 0)) {
        if (tk.kind == T_WORD) {
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (tk.kind != T_LPAREN)
                return FAIL(ps, tk.at, "expected '(' after abs");
        }
        close = tk.kind == T_BAR ? T_BAR : T_RPAREN;
        g->absolute = 1;
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    }
    token vtk = tk;
    if (goal_var(ps, &tk, &var) != SW_OK)
        return ps->status;
    g->var = (sw_lesson_var)var;
    if (negate && !var_is_bool(var))
        return FAIL(ps, vtk.at, "'not' goes with a yes/no variable (blown, compare, ghost, paused, "
                    "recorded, phase, region), not '%s'; expected e.g. 'not blown'", vtk.text);
    if (g->absolute && (var_is_bool(var) || var_is_name(var)))
        return FAIL(ps, vtk.at, "|...| goes around a number, not '%s'", vtk.text);
    if (var_available(ps, &vtk, var) != SW_OK)
        return ps->status;
    if (var == SW_LV_PARAM) {
        token ptk;
        if (lex(ps, &pos, &ptk) != SW_OK)
            return ps->status;
        int idx = ptk.kind == T_WORD ? sw_scene_param_index(ps->scene, ptk.text) : -1;
        if (idx < 0) {
            char names[200];
            sw_scene_param_names(ps->scene, names, sizeof names);
            return FAIL(ps, ptk.at, "expected a parameter of scene '%s' after 'param' (%s)%s%s%s",
                        ps->scene->name, names, ptk.kind == T_END ? "" : ", not '",
                        ptk.kind == T_END ? "" : ptk.text, ptk.kind == T_END ? "" : "'");
        }
        g->param = ps->scene->params[idx].name;
    }
    if (close != T_END) {
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
        if ((int)tk.kind != close)
            return FAIL(ps, tk.at, "expected '%c' to close the absolute value", close == T_BAR ? '|' : ')');
    }
    if (lex(ps, &pos, &tk) != SW_OK)
        return ps->status;
    /* "is" and "is not" read better in goals on names and yes/no. */
    if (tk.kind == T_WORD && strcmp(tk.text, "is") == 0) {
        size_t save = pos;
        token nt;
        if (lex(ps, &pos, &nt) != SW_OK)
            return ps->status;
        if (nt.kind == T_WORD && strcmp(nt.text, "not") == 0) {
            strcpy(tk.text, "!=");
        } else {
            strcpy(tk.text, "==");
            pos = save;
        }
        tk.kind = T_OP;
    }

    if (var_is_bool(var)) {
        g->op = SW_LOP_EQ;
        g->value = negate ? 0 : 1;
        if (tk.kind == T_OP && !negate && (strcmp(tk.text, "==") == 0 || strcmp(tk.text, "!=") == 0)) {
            int ne = tk.text[0] == '!';
            if (lex(ps, &pos, &tk) != SW_OK || goal_bool_value(ps, &tk, &g->value) != SW_OK)
                return ps->status;
            if (ne)
                g->value = 1 - g->value;
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
        }
    } else if (var_is_name(var)) {
        int in = tk.kind == T_WORD && strcmp(tk.text, "in") == 0;
        if (!in && !(tk.kind == T_OP && (strcmp(tk.text, "==") == 0 || strcmp(tk.text, "!=") == 0)))
            return FAIL(ps, tk.at, "expected ==, != or 'in' after %s", vtk.text);
        g->op = in ? SW_LOP_IN : tk.text[0] == '!' ? SW_LOP_NE : SW_LOP_EQ;
        for (;;) {
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (tk.kind == T_COMMA && g->nnames > 0)
                continue;
            if (tk.kind == T_END && g->nnames > 0)
                break;
            if (tk.kind != T_WORD)
                return FAIL(ps, tk.at, "expected %s name here", var == SW_LV_SCENE ? "a scene" : "an integrator");
            if (g->nnames == SW_LESSON_MAX_NAMES)
                return FAIL(ps, tk.at, "too many names after 'in'; expected at most %d", SW_LESSON_MAX_NAMES);
            if (var == SW_LV_SCENE) {
                const sw_scene *sc = sw_scene_find(tk.text);
                if (!sc) {
                    char names[300], near[80];
                    sw_scene_names(names, sizeof names);
                    return FAIL(ps, tk.at, "unknown scene '%s'%s; expected one of %s", tk.text,
                                sw_lp_suggest("", tk.text, sw_lp_scene_at, NULL, sw_scene_count(), near, sizeof near), names);
                }
                g->names[g->nnames++] = sc->name;
            } else {
                const sw_integrator *m;
                if (goal_method(ps, &tk, &m) != SW_OK)
                    return ps->status;
                g->names[g->nnames++] = m->name;
            }
            if (!in) {
                if (lex(ps, &pos, &tk) != SW_OK)
                    return ps->status;
                break;
            }
        }
    } else {
        int percent = var == SW_LV_ENERGY_DRIFT;
        if (tk.kind == T_WORD && strcmp(tk.text, "near") == 0) {
            g->op = SW_LOP_NEAR;
            if (goal_number(ps, &pos, percent, &g->value) != SW_OK)
                return ps->status;
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (!(tk.kind == T_WORD && strcmp(tk.text, "within") == 0))
                return FAIL(ps, tk.at, "expected 'within TOLERANCE' after 'near %g'", g->value);
            size_t tol_at = pos;
            while (tol_at < ps->lnlen && sw_lp_blank(ps->ln[tol_at]))
                tol_at++;
            if (goal_number(ps, &pos, percent, &g->tol) != SW_OK)
                return ps->status;
            if (!(g->tol > 0))
                return FAIL(ps, tol_at, "the tolerance after 'within' must be positive");
        } else if (tk.kind == T_OP && strcmp(tk.text, "!") != 0) {
            static const char *const ops[] = { "==", "!=", "<", "<=", ">", ">=" };
            for (int i = 0; i < 6; i++)
                if (strcmp(tk.text, ops[i]) == 0)
                    g->op = (sw_lesson_op)i;
            if (goal_number(ps, &pos, percent, &g->value) != SW_OK)
                return ps->status;
        } else {
            return FAIL(ps, tk.at, "expected a comparison after %s: one of == != < <= > >= or "
                        "'near X within Y'", vtk.text);
        }
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    }
    if (tk.kind != T_END)
        return FAIL(ps, tk.at, "unexpected '%s' after the goal; expected the end of the line "
                    "(write one condition per @goal)", tk.text[0] ? tk.text : "?");
    return SW_OK;
}


static int goal_method(sw_lp_parser *ps, const token *tk, const sw_integrator **out)
{
    if (sw_lp_find_integrator(ps, tk->text, tk->at, out) != SW_OK)
        return ps->status;
    char why[SW_ERRLEN];
    if (sw_lp_system_accepts(ps, *out, why, sizeof why) != SW_OK)
        return FAIL(ps, tk->at, "this goal can never be met on scene '%s': %s", ps->scene->name, why);
    return SW_OK;
}
int sw_lp_goal(sw_lp_parser *ps, size_t pos)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    if (sw_lp_need_scene(ps, "@goal") != SW_OK)
        return ps->status;
    if (pg->ngoals == SW_LESSON_MAX_GOALS)
        return FAIL(ps, 0, "too many goals on this page; expected at most %d (split the page)",
                    SW_LESSON_MAX_GOALS);
    sw_lesson_goal *g = &pg->goals[pg->ngoals];
    if (parse_goal(ps, pos, g) != SW_OK)
        return ps->status;
    /* whole-page checks point at the goal's expression */
    while (pos < ps->lnlen && sw_lp_blank(ps->ln[pos]))
        pos++;
    ps->at_goal[pg->ngoals] = (sw_lp_where){ ps->line, sw_lp_col(ps, pos) };
    pg->ngoals++;
    ps->hint_to = HINT_GOAL;
    return SW_OK;
}
