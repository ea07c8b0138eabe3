/* One-shot T1 for whole-process timing: the hand-written C/MPFR tanh-sinh of
   ../shared/bench/ts_mpfr.c (included unchanged, its own main renamed away),
   run once per process at one precision, nodes generated on the fly, no
   verification. This is the "C T1, same digits" column of bench/cold.sh.
   Build: gcc -O2 -I ../shared/bench -o ts_once bench/ts_once.c -lmpfr -lgmp -lm
   Run:   ./ts_once 100      -> prints T1 to 100 digits */
#define main ts_mpfr_main
#include "ts_mpfr.c"
#undef main

int main(int argc, char **argv) {
  int d = argc > 1 ? atoi(argv[1]) : 100;
  P = (mpfr_prec_t)ceil(d * 3.321928094887362) + 16;
  mpfr_inits2(P, th0, D, half, k2, A, c4gr, s0, c0, one, hh, sh, ch, sa, ca, cth, M, tmp, den, pi2,
              t, u, e, ei, cs, (mpfr_ptr)0);
  mpfr_set_ui(th0, 1, MPFR_RNDN); mpfr_div_ui(th0, th0, 10, MPFR_RNDN);
  mpfr_set_ui(D, 8, MPFR_RNDN); mpfr_div_ui(D, D, 10, MPFR_RNDN);
  mpfr_mul_2si(half, D, -1, MPFR_RNDN);
  mpfr_set_ui(k2, 1, MPFR_RNDN); mpfr_mul_2si(k2, k2, -1, MPFR_RNDN);
  mpfr_set_ui(A, 1, MPFR_RNDN); mpfr_div_ui(A, A, 3, MPFR_RNDN);
  mpfr_set_ui(c4gr, 2, MPFR_RNDN);
  mpfr_sin_cos(s0, c0, th0, MPFR_RNDN);
  mpfr_const_pi(pi2, MPFR_RNDN); mpfr_mul_2si(pi2, pi2, -1, MPFR_RNDN);
  for (int l = 0; l < 40; l++) { cache[l] = NULL; ncache[l] = 0; }
  mpfr_t S; mpfr_init2(S, P);
  int levels;
  integrate(S, 0, &levels);
  mpfr_printf("%.*Rg\n", d, S);
  return 0;
}
