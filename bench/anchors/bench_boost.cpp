// Anchor: Boost.Math over MPFR (boost::multiprecision::mpfr_float_backend<D>)
// on the ideal tasks, as a C++ user would write them:
//   T1   tanh_sinh on the raw integrand, with Boost's two-argument form f(x, xc)
//        (xc the distance to the nearer end, so the singular end's distance is
//        exact), and tanh_sinh on the v-substituted integrand (theta = th0 + v^2)
//   T2   toms748_solve on the separation condition over [0.8, 1.2] (T2: m2 = 1,
//        T2b: m2 = 2)
//   T3   theta at 1000 times: Newton in v on t(v), each step integrating from the
//        previous point by gauss_kronrod<Real, 31> (Boost has no arbitrary-
//        precision ODE solver of its own for this)
// One JSON line per task and precision: CPU seconds of the first call (cold:
// the integrator object built, its nodes generated) and the median of warm
// repeats with the same object.
//
// Build: g++ -O2 -std=c++17 -o bench_boost bench/anchors/bench_boost.cpp -lmpfr -lgmp
// Run:   ./bench_boost --t3-end T_END --t3-out DIR 30 100 300 1000
//        (T3 at the digits in --t3-digits, default 30,100; T_END from ref/reference.json)
// Boost 1.74: tanh_sinh<mpfr> must be given min_complement (its default one
// raises rounding_error: boostorg/math issue 380).
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace mpx = boost::multiprecision;
namespace quad = boost::math::quadrature;

static double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

template <class Real>
static std::string text(const Real &x, int digits) {
  return x.str(digits, std::ios_base::scientific);
}

// times fn: cold = first call, then warm repeats until 3 runs and 10 s, at most 9
template <class F>
static void timed(F fn, double &cold, double &warm, int &runs) {
  double c = cpu_now();
  fn();
  cold = cpu_now() - c;
  std::vector<double> t;
  double start = cpu_now();
  while (t.size() < 9 && (t.size() < 3 || cpu_now() - start < 10)) {
    c = cpu_now();
    fn();
    t.push_back(cpu_now() - c);
  }
  warm = median(t);
  runs = (int)t.size();
}

static void emit(const char *task, int d, const std::string &method, const std::string &value, double cold,
                 double warm, int runs, const std::string &extra = "") {
  std::printf("{\"tool\":\"boost\",\"task\":\"%s\",\"digits\":%d,\"method\":\"%s\",\"value\":\"%s\","
              "\"cold_s\":%.6g,\"cpu_median_s\":%.6g,\"runs\":%d%s}\n",
              task, d, method.c_str(), value.c_str(), cold, warm, runs, extra.c_str());
  std::fflush(stdout);
}

template <unsigned D>
struct Tasks {
  using Real = mpx::number<mpx::mpfr_float_backend<D>, mpx::et_off>;
  Real th0 = Real(1) / 10, th1 = Real(9) / 10, k2 = Real(1) / 2, gr = Real(1) / 2;

  Real A(int m2) const { return Real(m2) / (Real(3) / 2 + Real(3) / 2 * m2); }

  Real M(const Real &c, const Real &a) const { return 1 + k2 - a * (c - k2) * (c - k2); }

  // the raw integrand at th0 + delta, delta exact
  Real raw(const Real &delta) const {
    Real h = delta / 2, sh = sin(h), ch = cos(h);
    Real s0 = sin(th0), c0 = cos(th0);
    Real diff = 2 * sh * (s0 * ch + c0 * sh);  // cos th0 - cos th
    Real c = c0 - diff;
    return sqrt(M(c, A(1)) / (2 * gr * diff));
  }

  // dt/dv, theta = th0 + v^2
  Real rate(const Real &v) const {
    Real h = v * v / 2;
    Real sinc = h == 0 ? Real(1) : sin(h) / h;
    return 2 * sqrt(M(cos(th0 + 2 * h), A(1)) / (2 * gr * sin(th0 + h) * sinc));
  }

  Real sep_condition(const Real &x, int m2) const {
    Real a = A(m2), c = cos(x), s = sin(x);
    Real m = M(c, a);
    Real w2 = 2 * gr * (1 - c) / m;
    Real acc = (gr - a * (c - k2) * w2) * s / m;
    return w2 - gr * c + a * s * ((c - k2) * acc - s * w2);
  }

  void t1() {
    Real eps = std::numeric_limits<Real>::epsilon();
    Real tol = boost::math::tools::root_epsilon<Real>();
    {
      Real value;
      double cold, warm;
      int runs;
      size_t levels = 0;
      std::unique_ptr<quad::tanh_sinh<Real>> ts;
      timed(
          [&] {
            if (!ts) ts.reset(new quad::tanh_sinh<Real>(15, eps * eps));
            Real err;
            value = ts->integrate(
                [&](const Real &x, const Real &xc) { return raw(xc < 0 ? Real(-xc) : Real(x - th0)); }, th0, th1,
                tol, &err, nullptr, &levels);
          },
          cold, warm, runs);
      emit("T1", D, "tanh_sinh, raw integrand (x, xc)", text(value, D + 5), cold, warm, runs,
           ",\"levels\":" + std::to_string(levels));
    }
    {
      Real value;
      double cold, warm;
      int runs;
      std::unique_ptr<quad::tanh_sinh<Real>> ts;
      timed(
          [&] {
            if (!ts) ts.reset(new quad::tanh_sinh<Real>(15, eps * eps));
            value = ts->integrate([&](const Real &v) { return rate(v); }, Real(0), sqrt(th1 - th0), tol);
          },
          cold, warm, runs);
      emit("T1", D, "tanh_sinh, theta = theta0 + v^2", text(value, D + 5), cold, warm, runs);
    }
  }

  void t2(const char *task, int m2) {
    Real value;
    double cold, warm;
    int runs;
    timed(
        [&] {
          boost::uintmax_t it = 200;
          auto r = boost::math::tools::toms748_solve([&](const Real &x) { return sep_condition(x, m2); },
                                                     Real("0.8"), Real("1.2"),
                                                     boost::math::tools::eps_tolerance<Real>(), it);
          value = (r.first + r.second) / 2;
        },
        cold, warm, runs);
    emit(task, D, "toms748_solve on [0.8, 1.2]", text(value, D + 5), cold, warm, runs);
  }

  void t3(const std::string &t_end, const std::string &out_dir) {
    std::vector<Real> theta(1000);
    double cold, warm;
    int runs;
    Real T(t_end);
    // Newton stops at the rounding level of the residual
    Real tol = 100 * std::numeric_limits<Real>::epsilon();
    // Boost's default tolerance, sqrt(epsilon): the Kronrod-Gauss difference is the
    // Gauss rule's error, the Kronrod sum's own error is far smaller (the pieces
    // are short: about the 47th power of their width over the distance to the
    // nearest singularity, 0.45); an epsilon-sized tolerance never stops bisecting
    Real gk_tol = boost::math::tools::root_epsilon<Real>();
    timed(
        [&] {
          Real v0 = 0, t0 = 0;
          theta[0] = th0;
          std::vector<std::pair<Real, Real>> hist{{Real(0), Real(0)}};
          for (int i = 1; i < 1000; i++) {
            Real t = T * i / 999;
            Real v;
            if (hist.size() >= 3) {  // quadratic extrapolation of v in t
              auto &[ta, va] = hist[hist.size() - 3];
              auto &[tb, vb] = hist[hist.size() - 2];
              auto &[tc, vc] = hist[hist.size() - 1];
              v = va * (t - tb) * (t - tc) / ((ta - tb) * (ta - tc)) +
                  vb * (t - ta) * (t - tc) / ((tb - ta) * (tb - tc)) +
                  vc * (t - ta) * (t - tb) / ((tc - ta) * (tc - tb));
            } else {
              v = v0 + (t - t0) / rate(v0);
            }
            for (int k = 0; k < 60; k++) {
              Real piece = quad::gauss_kronrod<Real, 31>::integrate([&](const Real &x) { return rate(x); }, v0, v,
                                                                    15, gk_tol);
              Real r = rate(v);
              Real step = (t0 + piece - t) / r;
              if (abs(step) < tol) {
                v -= step;
                t0 = t0 + piece - step * r;
                break;
              }
              v -= step;
            }
            v0 = v;
            hist.push_back({t, v});
            theta[i] = th0 + v * v;
          }
        },
        cold, warm, runs);
    std::ofstream f(out_dir + "/T3_boost_" + std::to_string(D) + ".txt");
    for (auto &x : theta) f << text(x, D + 5) << "\n";
    emit("T3", D, "Newton in v on incremental gauss_kronrod<31>", text(theta[999], D + 5), cold, warm, runs);
  }
};

template <unsigned D>
static void run(const std::set<int> &t3_digits, const std::string &t_end, const std::string &out_dir) {
  Tasks<D> t;
  t.t1();
  t.t2("T2", 1);
  t.t2("T2b", 2);
  if (t3_digits.count(D) && !t_end.empty()) t.t3(t_end, out_dir);
}

int main(int argc, char **argv) {
  std::set<int> t3_digits{30, 100};
  std::string t_end, out_dir = ".";
  std::vector<int> digits;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    if (a == "--t3-end" && i + 1 < argc) {
      t_end = argv[++i];
    } else if (a == "--t3-out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (a == "--t3-digits" && i + 1 < argc) {
      t3_digits.clear();
      std::stringstream ss(argv[++i]);
      std::string x;
      while (std::getline(ss, x, ',')) t3_digits.insert(std::atoi(x.c_str()));
    } else {
      digits.push_back(std::atoi(argv[i]));
    }
  }
  for (int d : digits) {
    switch (d) {
      case 30: run<30>(t3_digits, t_end, out_dir); break;
      case 100: run<100>(t3_digits, t_end, out_dir); break;
      case 300: run<300>(t3_digits, t_end, out_dir); break;
      case 1000: run<1000>(t3_digits, t_end, out_dir); break;
      default: std::fprintf(stderr, "digits %d: not compiled in (30, 100, 300, 1000)\n", d);
    }
  }
  return 0;
}
