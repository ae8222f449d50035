#include "seepage_column.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lituya::verify {

namespace {

double skeleton_compliance(const SeepageColumn& c) {
  return c.constrained_modulus > 0 ? 1 / c.constrained_modulus : 0;
}

// Eq. (24)'s permeability, m2.
double permeability(const SeepageColumn& c) {
  const double n = c.porosity;
  return n * n * n * c.grain_diameter * c.grain_diameter / (150 * (1 - n) * (1 - n));
}

// n G = a v + b v |v| solved for the flux n v.
double darcy_forchheimer_flux(double a, double b, double n, double drive) {
  const double force = n * std::abs(drive);
  const double v = b > 0 ? (-a + std::sqrt(a * a + 4 * b * force)) / (2 * b) : force / a;
  return std::copysign(n * v, drive);
}

}  // namespace

double SeepageColumn::darcy_coefficient() const {
  return porosity * porosity * viscosity / permeability(*this);
}

double SeepageColumn::forchheimer_coefficient() const {
  return forchheimer
             ? 1.75 * std::pow(porosity, 1.5) * density / std::sqrt(150 * permeability(*this))
             : 0;
}

double SeepageColumn::flux(double drive) const {
  return darcy_forchheimer_flux(darcy_coefficient(), forchheimer_coefficient(), porosity, drive);
}

double SeepageColumn::steady_flux(double depth) const {
  return flux(density * gravity * (length + depth) / length);
}

std::vector<double> SeepageColumn::steady_depth(double d0, const std::vector<double>& times) const {
  std::vector<double> depth;
  double d = d0, t = 0;
  for (const double until : times) {
    const int steps = std::max(1, static_cast<int>(std::ceil((until - t) / 1e-4 - 1e-9)));
    const double step = (until - t) / steps;
    for (int k = 0; k < steps; ++k) {
      const double k1 = -steady_flux(d), k2 = -steady_flux(d + 0.5 * step * k1);
      const double k3 = -steady_flux(d + 0.5 * step * k2), k4 = -steady_flux(d + step * k3);
      d = std::max(0.0, d + step * (k1 + 2 * k2 + 2 * k3 + k4) / 6);
    }
    t = until;
    depth.push_back(d);
  }
  return depth;
}

double SeepageColumn::constrained_modulus_of(double youngs_modulus, double poisson_ratio) {
  return youngs_modulus * (1 - poisson_ratio) / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
}

double SeepageColumn::storage() const {
  return porosity / bulk_modulus + skeleton_compliance(*this);
}

SeepageColumn::Transient SeepageColumn::transient(double d0, const std::vector<double>& times,
                                                  int cells) const {
  const double s = storage();
  if (!(s > 0) || cells < 2) throw std::invalid_argument("SeepageColumn::transient: no storage");
  const double dz = length / cells, rho_g = density * gravity;
  const double compliance = skeleton_compliance(*this);
  const double a = darcy_coefficient(), b = forchheimer_coefficient();
  // The largest dq/dG is Darcy's, n^2 / a = kappa / mu.
  const double dt = 0.4 * s * dz * dz / (porosity * porosity / a);

  std::vector<double> p(cells + 1), q(cells);  // nodes from the plate (0) up; faces between
  for (int i = 0; i <= cells; ++i) p[i] = rho_g * (d0 + length - i * dz);
  const std::vector<double> p0 = p;
  double d = d0, outflow = 0, t = 0;
  Transient result;
  auto record = [&] {
    double stored = 0;  // interior nodes, the same weights as the update
    for (int i = 1; i < cells; ++i)
      stored += (s * (p[i] - p0[i]) - compliance * rho_g * (d - d0)) * dz;
    result.pond_depth.push_back(d);
    result.outflow.push_back(outflow);
    result.stored.push_back(stored);
  };
  for (const double until : times) {
    while (t < until - 1e-12) {
      const double step = std::min(dt, until - t);
      p[0] = 0;
      p[cells] = rho_g * d;
      for (int i = 0; i < cells; ++i)
        q[i] = darcy_forchheimer_flux(a, b, porosity, (p[i + 1] - p[i]) / dz + rho_g);
      const double pond_rate = -q[cells - 1];
      // The pond's weight on the column changes its total stress; the skeleton takes the
      // difference from the pore pressure (effective stress), so it swells as the pond falls.
      const double total_stress_rate = rho_g * pond_rate;
      for (int i = 1; i < cells; ++i)
        p[i] += step * ((q[i] - q[i - 1]) / dz + compliance * total_stress_rate) / s;
      d += step * pond_rate;
      outflow += step * q[0];
      t += step;
    }
    record();
  }
  return result;
}

}  // namespace lituya::verify
