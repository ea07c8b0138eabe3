/* Anchor: a hand-written tanh-sinh quadrature in C over MPFR for T1, the time
   from rest at theta0 = 1/10 to theta1 = 9/10 (identical solid cylinders, both
   contacts rolling):
       T1 = int_{th0}^{th1} sqrt(M(th) / (2 (g/r) (cos th0 - cos th))) dth,
       M = 1 + k2 - A (cos th - k2)^2,  A = 1/3, k2 = 1/2, g/r = 1/2.
   The rule hands the integrand the exact distance d = th - th0 of each node
   from the singular end (computed from exp(-2u), never as th - th0), and
   cos th0 - cos th = 2 sin(d/2) sin(th0 + d/2): one sin_cos of d/2, one sqrt,
   one division and about ten multiplications per node. Levels h = 2^-l, each
   adding the odd multiples; the sum stops when the last level changed it by
   less than 10^-(d/2 + 2) (the error squares from level to level).

   Build: gcc -O2 -o ts_mpfr bench/anchors/ts_mpfr.c -lmpfr -lgmp -lm
   Run:   ./ts_mpfr 30 100 300 1000   one JSON line per precision: cold CPU
                                       (nodes generated) and best of warm repeats
          ./ts_mpfr --once 100        T1 once, as a one-shot program (bench/cold.sh)
          ./ts_mpfr --count 100 REF   evaluations of the first level whose value is
                                       within 10^-100 of REF (relative), JSON */
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAXLEV 24

static mpfr_prec_t prec;
static mpfr_t th0, len, s0, c0, A, k2, two_gr;

/* one level's nodes: distance from the left end and from the right end, weight */
typedef struct {
  int n;
  mpfr_t *dl, *dr, *w;
} level_t;
static level_t lev[MAXLEV];
static int lev_built[MAXLEV];

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void setup(int digits) {
  prec = (mpfr_prec_t)ceil(digits * 3.3219280948873623) + 16;
  mpfr_inits2(prec, th0, len, s0, c0, A, k2, two_gr, (mpfr_ptr)0);
  mpfr_set_ui(th0, 1, MPFR_RNDN);
  mpfr_div_ui(th0, th0, 10, MPFR_RNDN);
  mpfr_set_ui(len, 8, MPFR_RNDN);
  mpfr_div_ui(len, len, 10, MPFR_RNDN); /* th1 - th0 = 8/10 */
  mpfr_sin_cos(s0, c0, th0, MPFR_RNDN);
  mpfr_set_ui(A, 1, MPFR_RNDN);
  mpfr_div_ui(A, A, 3, MPFR_RNDN);
  mpfr_set_d(k2, 0.5, MPFR_RNDN);
  mpfr_set_ui(two_gr, 1, MPFR_RNDN); /* 2 g / r */
  memset(lev_built, 0, sizeof lev_built);
}

static void teardown(void) {
  for (int l = 0; l < MAXLEV; l++)
    if (lev_built[l]) {
      for (int i = 0; i < lev[l].n; i++) mpfr_clears(lev[l].dl[i], lev[l].dr[i], lev[l].w[i], (mpfr_ptr)0);
      free(lev[l].dl); free(lev[l].dr); free(lev[l].w);
      lev_built[l] = 0;
    }
  mpfr_clears(th0, len, s0, c0, A, k2, two_gr, (mpfr_ptr)0);
  mpfr_free_cache();
}

/* f at the node th0 + d */
static void integrand(mpfr_t out, const mpfr_t d, mpfr_t *tmp) {
  mpfr_ptr sh = tmp[0], ch = tmp[1], x = tmp[2], c = tmp[3], y = tmp[4];
  mpfr_div_2ui(x, d, 1, MPFR_RNDN);
  mpfr_sin_cos(sh, ch, x, MPFR_RNDN);
  /* sin(th0 + d/2) = s0 ch + c0 sh */
  mpfr_mul(x, s0, ch, MPFR_RNDN);
  mpfr_fma(x, c0, sh, x, MPFR_RNDN);
  /* cos th0 - cos th = 2 sh sin(th0 + d/2) */
  mpfr_mul(y, sh, x, MPFR_RNDN);
  mpfr_mul_2ui(y, y, 1, MPFR_RNDN);
  /* cos th = c0 - y */
  mpfr_sub(c, c0, y, MPFR_RNDN);
  mpfr_sub(c, c, k2, MPFR_RNDN);
  mpfr_sqr(c, c, MPFR_RNDN);
  mpfr_mul(c, c, A, MPFR_RNDN);
  mpfr_ui_sub(c, 1, c, MPFR_RNDN);
  mpfr_add(c, c, k2, MPFR_RNDN); /* M */
  mpfr_mul(y, y, two_gr, MPFR_RNDN);
  mpfr_div(out, c, y, MPFR_RNDN);
  mpfr_sqrt(out, out, MPFR_RNDN);
}

/* nodes s = k h (k odd at level l >= 1; k >= 0 at level 0), h = 2^-l, until the
   weight falls below 2^-(prec + 40) relative */
static void build_level(int l, mpfr_t *tmp) {
  int cap = 64, n = 0;
  level_t *L = &lev[l];
  L->dl = malloc(cap * sizeof(mpfr_t)); L->dr = malloc(cap * sizeof(mpfr_t)); L->w = malloc(cap * sizeof(mpfr_t));
  mpfr_ptr s = tmp[0], u = tmp[1], e = tmp[2], ch = tmp[3], t = tmp[4], pi2 = tmp[5];
  mpfr_const_pi(pi2, MPFR_RNDN);
  mpfr_div_2ui(pi2, pi2, 1, MPFR_RNDN);
  for (long k = (l == 0 ? 0 : 1);; k += (l == 0 ? 1 : 2)) {
    mpfr_set_si(s, k, MPFR_RNDN);
    mpfr_div_2ui(s, s, l, MPFR_RNDN);
    mpfr_sinh_cosh(u, ch, s, MPFR_RNDN);
    mpfr_mul(u, u, pi2, MPFR_RNDN);      /* u = pi/2 sinh s */
    mpfr_mul(ch, ch, pi2, MPFR_RNDN);    /* du/ds */
    mpfr_mul_2ui(e, u, 1, MPFR_RNDN);
    mpfr_neg(e, e, MPFR_RNDN);
    mpfr_exp(e, e, MPFR_RNDN);           /* E = exp(-2u) */
    mpfr_add_ui(t, e, 1, MPFR_RNDN);     /* 1 + E */
    if (n == cap) {
      cap *= 2;
      L->dl = realloc(L->dl, cap * sizeof(mpfr_t)); L->dr = realloc(L->dr, cap * sizeof(mpfr_t));
      L->w = realloc(L->w, cap * sizeof(mpfr_t));
    }
    mpfr_inits2(prec, L->dl[n], L->dr[n], L->w[n], (mpfr_ptr)0);
    /* x = th0 + len / (1 + E) on the right, th0 + len E / (1 + E) on the left */
    mpfr_div(L->dr[n], len, t, MPFR_RNDN);
    mpfr_mul(L->dl[n], L->dr[n], e, MPFR_RNDN);
    /* dx/ds = len du/ds / (2 cosh^2 u) = 2 len du/ds E / (1 + E)^2 */
    mpfr_mul(L->w[n], L->dl[n], ch, MPFR_RNDN);
    mpfr_div(L->w[n], L->w[n], t, MPFR_RNDN);
    mpfr_mul_2ui(L->w[n], L->w[n], 1, MPFR_RNDN);
    n++;
    /* the terms near the singular end fall like sqrt(E): stop when E < 2^-(2 prec + 40) */
    if (mpfr_zero_p(e) || mpfr_get_exp(e) < -2 * (mpfr_exp_t)prec - 40) break;
  }
  L->n = n;
  lev_built[l] = 1;
}

/* T1 by levels 0..; returns levels used; *evals integrand evaluations;
   with ref != NULL stops at the first level within 10^-digits of ref instead */
static int integrate(mpfr_t out, int digits, long *evals, const mpfr_t ref) {
  mpfr_t tmp[6], sum, prev, f, diff, tol;
  for (int i = 0; i < 6; i++) mpfr_init2(tmp[i], prec);
  mpfr_inits2(prec, sum, prev, f, diff, tol, (mpfr_ptr)0);
  mpfr_set_ui(tol, 10, MPFR_RNDN);
  mpfr_pow_si(tol, tol, ref ? -digits : -(digits / 2 + 2), MPFR_RNDN);
  mpfr_set_ui(sum, 0, MPFR_RNDN);
  *evals = 0;
  int l, done = 0;
  for (l = 0; l < MAXLEV && !done; l++) {
    if (!lev_built[l]) build_level(l, tmp);
    level_t *L = &lev[l];
    mpfr_set(prev, sum, MPFR_RNDN);
    if (l > 0) mpfr_div_2ui(sum, sum, 1, MPFR_RNDN); /* the halved step */
    mpfr_t part;
    mpfr_init2(part, prec);
    mpfr_set_ui(part, 0, MPFR_RNDN);
    for (int i = 0; i < L->n; i++) {
      integrand(f, L->dr[i], tmp);
      mpfr_fma(part, f, L->w[i], part, MPFR_RNDN);
      (*evals)++;
      if (i == 0 && l == 0) continue; /* s = 0: one node, evaluated once */
      integrand(f, L->dl[i], tmp);
      mpfr_fma(part, f, L->w[i], part, MPFR_RNDN);
      (*evals)++;
    }
    mpfr_div_2ui(part, part, l, MPFR_RNDN); /* times h */
    mpfr_add(sum, sum, part, MPFR_RNDN);
    mpfr_clear(part);
    if (ref) {
      mpfr_sub(diff, sum, ref, MPFR_RNDN);
      mpfr_div(diff, diff, ref, MPFR_RNDN);
      done = mpfr_cmpabs(diff, tol) < 0;
    } else if (l >= 2) {
      mpfr_sub(diff, sum, prev, MPFR_RNDN);
      mpfr_div(diff, diff, sum, MPFR_RNDN);
      done = mpfr_cmpabs(diff, tol) < 0;
    }
  }
  mpfr_set(out, sum, MPFR_RNDN);
  for (int i = 0; i < 6; i++) mpfr_clear(tmp[i]);
  mpfr_clears(sum, prev, f, diff, tol, (mpfr_ptr)0);
  return l;
}

int main(int argc, char **argv) {
  if (argc >= 3 && !strcmp(argv[1], "--once")) {
    int d = atoi(argv[2]);
    setup(d);
    mpfr_t v;
    mpfr_init2(v, prec);
    long ev;
    integrate(v, d, &ev, NULL);
    mpfr_printf("%.*Rg\n", d, v);
    return 0;
  }
  if (argc >= 4 && !strcmp(argv[1], "--count")) {
    int d = atoi(argv[2]);
    setup(d);
    mpfr_t v, ref;
    mpfr_inits2(prec, v, ref, (mpfr_ptr)0);
    mpfr_set_str(ref, argv[3], 10, MPFR_RNDN);
    long ev;
    int l = integrate(v, d, &ev, ref);
    printf("{\"digits\": %d, \"tsraw_dyadic_n\": %ld, \"tsraw_dyadic_h\": %.17g}\n", d, ev, ldexp(1.0, -(l - 1)));
    return 0;
  }
  for (int a = 1; a < argc; a++) {
    int d = atoi(argv[a]);
    setup(d);
    mpfr_t v;
    mpfr_init2(v, prec);
    long ev;
    double c = cpu_now();
    int levels = integrate(v, d, &ev, NULL);
    double cold = cpu_now() - c, best = 1e30;
    int reps = d >= 1000 ? 5 : 9;
    for (int r = 0; r < reps; r++) {
      c = cpu_now();
      integrate(v, d, &ev, NULL);
      double x = cpu_now() - c;
      if (x < best) best = x;
    }
    char *s = NULL;
    mpfr_asprintf(&s, "%.*Rg", d + 5, v);
    printf("{\"digits\": %d, \"prec_bits\": %ld, \"levels\": %d, \"n_evals\": %ld, \"cold_cpu_s\": %.6g, "
           "\"warm_cpu_s_best\": %.6g, \"ns_per_eval\": %.0f, \"value\": \"%s\"}\n",
           d, (long)prec, levels, ev, cold, best, best / ev * 1e9, s);
    fflush(stdout);
    mpfr_free_str(s);
    mpfr_clear(v);
    teardown();
  }
  return 0;
}
