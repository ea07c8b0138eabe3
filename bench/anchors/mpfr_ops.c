/* This machine's cost of single MPFR operations at the anchors' precisions
   (ceil(d log2 10) bits for d = 30, 100, 300, 1000): nanoseconds per call, the
   smallest of 3 timed loops of CPU time. Prints a markdown table that
   bench/ratios.py reads for the tanh-sinh floor of T1.
   Build: gcc -O2 -o mpfr_ops bench/anchors/mpfr_ops.c -lmpfr -lgmp -lm */
#include <math.h>
#include <mpfr.h>
#include <stdio.h>
#include <time.h>

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

enum { MUL, DIV, SQRT, COS, SIN, SINCOS, ADD, EXP, NOPS };
static const char *names[NOPS] = {"mul", "div", "sqrt", "cos", "sin", "sin_cos", "add", "exp"};

static double time_op(int op, mpfr_prec_t p) {
  mpfr_t x, y, z, w;
  mpfr_inits2(p, x, y, z, w, (mpfr_ptr)0);
  mpfr_const_pi(x, MPFR_RNDN);
  mpfr_div_ui(x, x, 7, MPFR_RNDN); /* an angle with every bit set */
  mpfr_sqrt_ui(y, 3, MPFR_RNDN);
  long n = op == COS || op == SIN || op == SINCOS || op == EXP ? 2000 : 200000;
  if (p > 3000) n /= 10;
  double best = 1e30;
  for (int rep = 0; rep < 3; rep++) {
    double c = cpu_now();
    for (long i = 0; i < n; i++) {
      switch (op) {
        case MUL: mpfr_mul(z, x, y, MPFR_RNDN); break;
        case DIV: mpfr_div(z, x, y, MPFR_RNDN); break;
        case SQRT: mpfr_sqrt(z, y, MPFR_RNDN); break;
        case COS: mpfr_cos(z, x, MPFR_RNDN); break;
        case SIN: mpfr_sin(z, x, MPFR_RNDN); break;
        case SINCOS: mpfr_sin_cos(z, w, x, MPFR_RNDN); break;
        case ADD: mpfr_add(z, x, y, MPFR_RNDN); break;
        case EXP: mpfr_exp(z, x, MPFR_RNDN); break;
      }
    }
    double t = (cpu_now() - c) / n;
    if (t < best) best = t;
  }
  mpfr_clears(x, y, z, w, (mpfr_ptr)0);
  return best * 1e9;
}

int main(void) {
  int digits[] = {30, 100, 300, 1000};
  printf("| digits | bits |");
  for (int o = 0; o < NOPS; o++) printf(" %s ns |", names[o]);
  printf("\n|---|---|");
  for (int o = 0; o < NOPS; o++) printf("---|");
  printf("\n");
  for (int i = 0; i < 4; i++) {
    mpfr_prec_t p = (mpfr_prec_t)ceil(digits[i] * 3.3219280948873623);
    printf("| %d | %ld |", digits[i], (long)p);
    for (int o = 0; o < NOPS; o++) printf(" %.0f |", time_op(o, p));
    printf("\n");
    fflush(stdout);
  }
  printf("\nsmallest of 3 timed loops (CPU time); MPFR %s, GMP %s\n", mpfr_get_version(), gmp_version);
  return 0;
}
