#include "sim/solid/elasticity_peer2018.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <sstream>

#include "sim/solid/fixed_particles.h"

namespace sim {
namespace {

struct Lame {
  Real mu;      // [Pa] shear modulus
  Real lambda;  // [Pa] first Lame parameter
};

Lame lameOf(const Material& m) {
  const Real E = m.youngsModulus, nu = m.poissonRatio;
  return {E / (2.0 * (1.0 + nu)), E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))};
}

// Rotational part of A by Mueller, Bender, Chentanez & Macklin 2016 ("A robust method to extract
// the rotational part of deformations", MIG '16), eq. 7, starting from q (the last step's
// rotation): robust for degenerate and inverted A, where a polar decomposition by SVD flips
// arbitrarily.
Eigen::Quaterniond extractRotation(const Mat3& A, Eigen::Quaterniond q) {
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Mat3 R = q.toRotationMatrix();
    const Vec3 omega =
        (R.col(0).cross(A.col(0)) + R.col(1).cross(A.col(1)) + R.col(2).cross(A.col(2))) /
        (std::abs(R.col(0).dot(A.col(0)) + R.col(1).dot(A.col(1)) + R.col(2).dot(A.col(2))) + 1e-9);
    const Real w = omega.norm();
    if (w < 1e-9) break;
    q = Eigen::Quaterniond(Eigen::AngleAxisd(w, omega / w)) * q;
    q.normalize();
  }
  return q;
}

Mat3 symmetricPart(const Mat3& A) { return 0.5 * (A + A.transpose()); }

using Vec9 = Eigen::Matrix<Real, 9, 1>;
using Mat9 = Eigen::Matrix<Real, 9, 9>;

// Linear and quadratic monomials of Y = X / h (scaled so that M is well conditioned).
Vec9 quadraticBasis(const Vec3& X, Real h) {
  const Vec3 Y = X / h;
  Vec9 q;
  q << Y.x(), Y.y(), Y.z(), Y.x() * Y.x(), Y.y() * Y.y(), Y.z() * Y.z(), Y.x() * Y.y(),
      Y.x() * Y.z(), Y.y() * Y.z();
  return q;
}

// Gradient weights a_j of a kernel-weighted least-squares fit of u_j - u_s by a quadratic
// polynomial (moving least squares, e.g. Belytschko et al. 1996): grad u ~ sum_j (u_j - u_s) a_j^T
// is then exact for linear AND quadratic fields, also at a surface, where the first-order
// correction evaluates the gradient at the neighbourhood's centroid instead of the particle and
// under-estimates bending strain (15 % of a 5-particle beam's bending energy). Returns false if the
// neighbourhood does not determine a quadratic (too few or coplanar neighbours).
bool quadraticGradientWeights(const std::vector<Vec3>& Xsj, const std::vector<Real>& w, Real h,
                              std::vector<Vec3>& a) {
  Mat9 M = Mat9::Zero();
  for (std::size_t k = 0; k < Xsj.size(); ++k) {
    const Vec9 q = quadraticBasis(Xsj[k], h);
    M += w[k] * q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Mat9> eigen(M);
  const Vec9 lambda = eigen.eigenvalues();  // ascending
  if (!(lambda[0] > 1e-8 * lambda[8])) return false;
  const Mat9 Minv =
      eigen.eigenvectors() * lambda.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
  a.resize(Xsj.size());
  for (std::size_t k = 0; k < Xsj.size(); ++k)
    a[k] = w[k] * (Minv * quadraticBasis(Xsj[k], h)).head<3>() / h;
  return true;
}

}  // namespace

ElasticityPeer2018::ElasticityPeer2018(const ElasticityParameters& parameters)
    : parameters_(parameters) {
  require(parameters_.hourglassStiffness >= 0.0, "elasticity: hourglass stiffness must be >= 0");
  require(parameters_.solverTolerance > 0.0 && parameters_.solverTolerance < 1.0,
          "elasticity: solver tolerance must be in (0, 1)");
  require(parameters_.maxSolverIterations > 0, "elasticity: max solver iterations must be > 0");
  require(parameters_.waveCourantNumber > 0.0, "elasticity: wave Courant number must be > 0");
  require(parameters_.couplingStepFactor >= 0.0,
          "elasticity: coupling step factor must be >= 0 (0 switches the coupling limit off)");
  require(parameters_.supportRadiusFactor == 0.0 ||
              (parameters_.supportRadiusFactor >= 1.0 && parameters_.supportRadiusFactor <= 4.0),
          "elasticity: support radius factor must be 0 (world kernel) or in [1, 4] spacings");
}

Real ElasticityPeer2018::waveSpeed(const Material& material) {
  const Lame l = lameOf(material);
  return std::sqrt((l.lambda + 2.0 * l.mu) / material.restDensity);
}

Real ElasticityPeer2018::maxTimeStep(const World& world) const {
  Real cMax = 0;
  for (const auto& m : world.materials)
    if (m.kind == MaterialKind::kElastic) cMax = std::max(cMax, waveSpeed(m));
  if (cMax <= 0) return Effect::maxTimeStep(world);
  Real dt = parameters_.waveCourantNumber * world.particleSpacing() / cMax;
  if (parameters_.couplingStepFactor <= 0 || bodyCount_ == 0) return dt;
  // Coupling limit for bodies that something else can load this step (see couplingStepFactor).
  const auto& p = world.particles;
  const NeighborList& nf = world.fluidNeighbors();
  const NeighborList& nw = world.wallNeighbors();
  const Index n = static_cast<Index>(p.size());
  if (idToSlot_.size() != static_cast<std::size_t>(n)) return dt;  // before attach()
  bodyLoaded_.assign(bodyCount_, 0);
  for (Index i = 0; i < n; ++i) {
    const std::int32_t s = idToSlot_[static_cast<std::size_t>(p.id[i])];
    if (s < 0) continue;
    auto& loaded = bodyLoaded_[static_cast<std::size_t>(bodyOf_[static_cast<std::size_t>(s)])];
    if (loaded) continue;
    if (nw.offsets[i + 1] > nw.offsets[i]) loaded = 1;
    for (Index k = nf.offsets[i]; k < nf.offsets[i + 1] && !loaded; ++k)
      if (p.material[nf.indices[k]] != p.material[i]) loaded = 1;
  }
  for (std::size_t b = 0; b < bodyCount_; ++b)
    if (bodyLoaded_[b]) dt = std::min(dt, parameters_.couplingStepFactor / bodyOmega_[b]);
  return dt;
}

// Thickness per body: surface particles are those with fewer than 3/4 of the body's largest
// reference-neighbour count (a lattice face keeps about half); the depth of every particle is its
// shortest path to a surface particle over the reference neighbour pairs (Dijkstra), and
// L = 2 max depth + d. A body made only of surface particles (one or two layers) gets L = d, an
// under-estimate by up to 2x for two layers: the limit errs towards shorter steps.
void ElasticityPeer2018::computeBodyThickness(Real spacing, const std::vector<Real>& waveSpeeds) {
  const std::size_t slots = slotId_.size();
  std::vector<std::size_t> maxCount(bodyCount_, 0);
  for (std::size_t s = 0; s < slots; ++s) {
    auto& m = maxCount[static_cast<std::size_t>(bodyOf_[s])];
    m = std::max(m, pairBegin_[s + 1] - pairBegin_[s]);
  }
  std::vector<Real> depth(slots, std::numeric_limits<Real>::infinity());
  using Entry = std::pair<Real, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t s = 0; s < slots; ++s)
    if (4 * (pairBegin_[s + 1] - pairBegin_[s]) <
        3 * maxCount[static_cast<std::size_t>(bodyOf_[s])]) {
      depth[s] = 0;
      queue.push({0.0, s});
    }
  while (!queue.empty()) {
    const auto [dist, s] = queue.top();
    queue.pop();
    if (dist > depth[s]) continue;
    for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
      const auto j = static_cast<std::size_t>(pairSlot_[k]);
      const Real candidate = dist + pairX_[k].norm();
      if (candidate < depth[j]) {
        depth[j] = candidate;
        queue.push({candidate, j});
      }
    }
  }
  bodyThickness_.assign(bodyCount_, 0.0);
  for (std::size_t s = 0; s < slots; ++s) {
    auto& t = bodyThickness_[static_cast<std::size_t>(bodyOf_[s])];
    if (std::isfinite(depth[s])) t = std::max(t, depth[s]);
  }
  bodyOmega_.resize(bodyCount_);
  for (std::size_t b = 0; b < bodyCount_; ++b) {
    bodyThickness_[b] = 2.0 * bodyThickness_[b] + spacing;
    bodyOmega_[b] = 0.5 * std::numbers::pi * waveSpeeds[b] / bodyThickness_[b];
  }
}

namespace {

// Particle index of each id; ids must be creation indices 0..n-1.
std::vector<Index> indicesById(const World& world) {
  const auto& p = world.particles;
  const std::size_t n = p.size();
  std::vector<Index> idToIndex(n);
  for (Index i = 0; i < n; ++i) {
    require(p.id[i] >= 0 && static_cast<std::size_t>(p.id[i]) < n,
            "elasticity: particle ids must be creation indices 0..n-1");
    idToIndex[static_cast<std::size_t>(p.id[i])] = i;
  }
  return idToIndex;
}

// Reference neighbours: same material (one body per material) within the support radius, found
// by binning the reference positions (the world's lists hold current, possibly moved positions).
// Each list is sorted by slot.
std::vector<std::vector<std::int32_t>> referenceNeighbours(
    const std::vector<Vec3>& X, const std::vector<std::int32_t>& materialOf, Real h) {
  const std::size_t slots = X.size();
  std::vector<std::vector<std::int32_t>> neighbours(slots);
  Vec3 lo = Vec3::Constant(1e300);
  for (const Vec3& x : X) lo = lo.cwiseMin(x);
  auto cellOf = [&](const Vec3& x) {
    return Eigen::Vector3i(static_cast<int>(std::floor((x.x() - lo.x()) / h)),
                           static_cast<int>(std::floor((x.y() - lo.y()) / h)),
                           static_cast<int>(std::floor((x.z() - lo.z()) / h)));
  };
  std::vector<std::pair<std::int64_t, std::int32_t>> keyed(slots);
  auto key = [](const Eigen::Vector3i& c) {
    return (static_cast<std::int64_t>(c.x()) << 42) | (static_cast<std::int64_t>(c.y()) << 21) |
           static_cast<std::int64_t>(c.z());
  };
  for (std::size_t s = 0; s < slots; ++s)
    keyed[s] = {key(cellOf(X[s])), static_cast<std::int32_t>(s)};
  std::sort(keyed.begin(), keyed.end());
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    const Eigen::Vector3i c = cellOf(X[s]);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Eigen::Vector3i cc = c + Eigen::Vector3i(dx, dy, dz);
          if (cc.minCoeff() < 0) continue;
          const std::int64_t k = key(cc);
          auto it =
              std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(k, std::int32_t(-1)));
          for (; it != keyed.end() && it->first == k; ++it) {
            const auto j = static_cast<std::size_t>(it->second);
            if (j == s || materialOf[j] != materialOf[s]) continue;
            if ((X[j] - X[s]).squaredNorm() < h * h)
              neighbours[s].push_back(static_cast<std::int32_t>(j));
          }
        }
    std::sort(neighbours[s].begin(), neighbours[s].end());
  }
  return neighbours;
}

}  // namespace

void ElasticityPeer2018::attach(World& world) {
  auto& p = world.particles;
  const std::size_t n = p.size();

  // Reference positions: the registry field if a restart already holds one, else the current x.
  const bool restart = p.fields.has(field::kReferencePosition);
  auto& reference = p.fields.addOrGet<Vec3>({field::kReferencePosition, "m", true, true});
  auto& rotation = p.fields.addOrGet<Mat3>({field::kElasticRotation, "1", true, false});
  fixedFlags(p);
  if (!restart)
    for (Index i = 0; i < n; ++i) {
      reference[i] = p.x[i];
      rotation[i].setIdentity();
    }

  const std::vector<Index> idToIndex = indicesById(world);
  const std::vector<Real> youngs = assignSlots(world, idToIndex);
  const std::size_t slots = slotId_.size();

  const Kernel kernel =
      parameters_.supportRadiusFactor > 0
          ? Kernel(world.kernel.kind(), parameters_.supportRadiusFactor * world.particleSpacing())
          : world.kernel;
  std::vector<Vec3> X(slots);
  for (std::size_t s = 0; s < slots; ++s)
    X[s] = reference[idToIndex[static_cast<std::size_t>(slotId_[s])]];
  std::vector<std::int32_t> materialOf(slots);
  for (std::size_t s = 0; s < slots; ++s)
    materialOf[s] = p.material[idToIndex[static_cast<std::size_t>(slotId_[s])]];
  const std::vector<std::vector<std::int32_t>> neighbours =
      referenceNeighbours(X, materialOf, kernel.supportRadius());

  countPairs(neighbours, X, kernel.supportRadius());
  buildPairs(neighbours, X, kernel, youngs);
  buildBodies(world, materialOf);

  slotIndex_.resize(slots);
  fixed_.resize(slots);
  mass_.resize(slots);
  energy_.resize(slots);
  for (auto* v : {&x_, &v_, &rhs_, &r_, &z_, &p_, &ap_, &grad_}) v->resize(slots);
  for (auto* m : {&rotation_, &defGrad_, &stress_, &precond_}) m->resize(slots);
}

std::vector<Real> ElasticityPeer2018::assignSlots(const World& world,
                                                  const std::vector<Index>& idToIndex) {
  const auto& p = world.particles;
  const std::size_t n = p.size();
  auto isElastic = [&](Index i) {
    return world.materials[p.material[i]].kind == MaterialKind::kElastic;
  };
  // Slots in id order, so the pair data do not depend on the current sort order.
  idToSlot_.assign(n, -1);
  slotId_.clear();
  for (std::size_t id = 0; id < n; ++id)
    if (isElastic(idToIndex[id])) {
      idToSlot_[id] = static_cast<std::int32_t>(slotId_.size());
      slotId_.push_back(static_cast<std::int32_t>(id));
    }
  const std::size_t slots = slotId_.size();
  volume_.resize(slots);
  mu_.resize(slots);
  lambda_.resize(slots);
  std::vector<Real> youngs(slots);
  for (std::size_t s = 0; s < slots; ++s) {
    const Index i = idToIndex[static_cast<std::size_t>(slotId_[s])];
    const Material& m = world.materials[p.material[i]];
    volume_[s] = world.restVolumeOf(i);
    const Lame l = lameOf(m);
    mu_[s] = l.mu;
    lambda_[s] = l.lambda;
    youngs[s] = m.youngsModulus;
  }
  return youngs;
}

void ElasticityPeer2018::countPairs(const std::vector<std::vector<std::int32_t>>& neighbours,
                                    const std::vector<Vec3>& X, Real h) {
  const std::size_t slots = neighbours.size();
  pairBegin_.assign(slots + 1, 0);
  for (std::size_t s = 0; s < slots; ++s) {
    if (neighbours[s].empty()) {
      std::ostringstream what;
      what << "elasticity: elastic particle id " << slotId_[s] << " at (" << X[s].transpose()
           << ") m has no elastic neighbour within the support radius " << h
           << " m; sample tissue with the world's particle spacing";
      throw SimError(what.str());
    }
    pairBegin_[s + 1] = pairBegin_[s] + neighbours[s].size();
  }
  const std::size_t pairs = pairBegin_[slots];
  pairSlot_.resize(pairs);
  pairReverse_.resize(pairs);
  pairGrad_.resize(pairs);
  pairX_.resize(pairs);
  pairHourglass_.resize(pairs);
  gradSum_.resize(slots);
}

void ElasticityPeer2018::buildPairs(const std::vector<std::vector<std::int32_t>>& neighbours,
                                    const std::vector<Vec3>& X, const Kernel& kernel,
                                    const std::vector<Real>& youngs) {
  const std::size_t slots = neighbours.size();
  const Real h = kernel.supportRadius();
  const Real alpha = parameters_.hourglassStiffness;
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    // Bonet & Lok 1999 correction: L_s makes F exact for affine deformations.
    Mat3 A = Mat3::Zero();
    for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
      const auto j = static_cast<std::size_t>(neighbours[s][k - pairBegin_[s]]);
      A += volume_[j] * (X[j] - X[s]) * kernel.gradW(X[s] - X[j]).transpose();
    }
    // Pseudo-inverse: a particle on an edge or corner can have a near-singular A; its singular
    // directions then get no correction instead of a huge one.
    // A^+ = (A^T A)^+ A^T from the eigen-decomposition of the symmetric A^T A.
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(A.transpose() * A);
    const Vec3 s2 = eigen.eigenvalues();  // ascending squared singular values
    Vec3 inv = Vec3::Zero();
    for (int c = 0; c < 3; ++c)
      if (s2[c] > 1e-6 * s2[2]) inv[c] = 1.0 / s2[c];
    const Mat3 Ainv =
        eigen.eigenvectors() * inv.asDiagonal() * eigen.eigenvectors().transpose() * A.transpose();
    const Mat3 L = Ainv.transpose();
    // Second-order weights where the neighbourhood supports them (needs a support of > 2 d so that
    // a surface particle sees two layers inwards); Bonet & Lok otherwise.
    std::vector<Vec3> quadratic, offsets;
    std::vector<Real> weights;
    bool second = false;
    if (parameters_.quadraticGradient) {
      for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
        const auto j = static_cast<std::size_t>(neighbours[s][k - pairBegin_[s]]);
        offsets.push_back(X[j] - X[s]);
        weights.push_back(kernel.W(offsets.back().norm()));
      }
      second = quadraticGradientWeights(offsets, weights, h, quadratic);
    }
    Vec3 b = Vec3::Zero();
    for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
      const auto j = static_cast<std::size_t>(neighbours[s][k - pairBegin_[s]]);
      const Vec3 Xsj = X[j] - X[s];
      pairSlot_[k] = static_cast<std::int32_t>(j);
      pairX_[k] = Xsj;
      pairGrad_[k] = second ? Vec3(quadratic[k - pairBegin_[s]] / volume_[j])
                            : Vec3(L * kernel.gradW(X[s] - X[j]));
      b += volume_[j] * pairGrad_[k];
      pairHourglass_[k] = alpha * 0.5 * (youngs[s] + youngs[j]) * volume_[s] * volume_[j] *
                          kernel.W(Xsj.norm()) / Xsj.squaredNorm();
      const auto& back = neighbours[j];
      const auto pos = std::lower_bound(back.begin(), back.end(), static_cast<std::int32_t>(s));
      pairReverse_[k] = pairBegin_[j] + static_cast<std::size_t>(pos - back.begin());
    }
    gradSum_[s] = b;
  }
}

// Bodies (one per elastic material), for the momentum correction in apply().
void ElasticityPeer2018::buildBodies(const World& world,
                                     const std::vector<std::int32_t>& materialOf) {
  const std::size_t slots = materialOf.size();
  std::vector<std::int32_t> materials(materialOf);
  std::sort(materials.begin(), materials.end());
  materials.erase(std::unique(materials.begin(), materials.end()), materials.end());
  bodyCount_ = materials.size();
  bodyOf_.resize(slots);
  bodyBegin_.assign(bodyCount_ + 1, 0);
  for (std::size_t s = 0; s < slots; ++s) {
    bodyOf_[s] = static_cast<std::int32_t>(
        std::lower_bound(materials.begin(), materials.end(), materialOf[s]) - materials.begin());
    ++bodyBegin_[static_cast<std::size_t>(bodyOf_[s]) + 1];
  }
  for (std::size_t b = 0; b < bodyCount_; ++b) bodyBegin_[b + 1] += bodyBegin_[b];
  bodySlots_.resize(slots);
  {
    std::vector<std::size_t> next(bodyBegin_.begin(), bodyBegin_.end() - 1);
    for (std::size_t s = 0; s < slots; ++s)
      bodySlots_[next[static_cast<std::size_t>(bodyOf_[s])]++] = s;
  }
  bodyFixed_.assign(bodyCount_, 0);
  {
    std::vector<Real> speeds(bodyCount_);
    for (std::size_t b = 0; b < bodyCount_; ++b)
      speeds[b] = waveSpeed(world.materials[materials[b]]);
    computeBodyThickness(world.particleSpacing(), speeds);
  }
}

void ElasticityPeer2018::mapSlots(const World& world) {
  const auto& p = world.particles;
  const Index n = static_cast<Index>(p.size());
  require(static_cast<std::size_t>(n) == idToSlot_.size(),
          "elasticity: the particle count changed after attach()");
  for (Index i = 0; i < n; ++i) {
    const std::int32_t s = idToSlot_[static_cast<std::size_t>(p.id[i])];
    if (s >= 0) slotIndex_[static_cast<std::size_t>(s)] = i;
  }
}

void ElasticityPeer2018::computeRotations() {
  const std::size_t slots = slotId_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    const Eigen::Quaterniond q0(rotation_[s]);
    rotation_[s] = extractRotation(defGrad_[s], q0.normalized()).toRotationMatrix();
  }
}

void ElasticityPeer2018::energyGradient(const std::vector<Vec3>& u, bool subtractIdentity,
                                        std::vector<Vec3>& out) {
  const std::size_t slots = slotId_.size();
  // Phase 1: F_s = sum_j V_j (u_j - u_s) g_sj^T (Peer 2018 eq. 7 with the corrected gradient).
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    Mat3 F = Mat3::Zero();
    for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
      const auto j = static_cast<std::size_t>(pairSlot_[k]);
      F += volume_[j] * (u[j] - u[s]) * pairGrad_[k].transpose();
    }
    defGrad_[s] = F;
  }
  if (subtractIdentity) computeRotations();
    // Phase 2: T_s = V_s R_s sigma_s + sum_j r_sj X_sj^T, the stress and the zero-energy-mode error
    // moment, both acting on the neighbours through g (Peer 2018 eq. 9-11; Ganzenmueller 2015 eq.
    // 20).
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    const Mat3& R = rotation_[s];
    Mat3 eps = symmetricPart(R.transpose() * defGrad_[s]);
    if (subtractIdentity) eps -= Mat3::Identity();
    const Mat3 sigma = 2.0 * mu_[s] * eps + lambda_[s] * eps.trace() * Mat3::Identity();
    Mat3 T = volume_[s] * R * sigma;
    for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
      const auto j = static_cast<std::size_t>(pairSlot_[k]);
      const Vec3 r =
          pairHourglass_[k] * (0.5 * (defGrad_[s] + defGrad_[j]) * pairX_[k] - (u[j] - u[s]));
      T += r * pairX_[k].transpose();
    }
    stress_[s] = T;
    if (subtractIdentity) {
      Real e =
          volume_[s] * (mu_[s] * eps.squaredNorm() + 0.5 * lambda_[s] * eps.trace() * eps.trace());
      for (std::size_t k = pairBegin_[s]; k < pairBegin_[s + 1]; ++k) {
        const auto j = static_cast<std::size_t>(pairSlot_[k]);
        e += 0.5 * pairHourglass_[k] *
             (0.5 * (defGrad_[s] + defGrad_[j]) * pairX_[k] - (u[j] - u[s])).squaredNorm();
      }
      energy_[s] = e;
    }
  }
  // Phase 3: gradient at slot a = V_a sum_j T_j g_ja - T_a b_a + sum_j c_aj ((F_a + F_j) X_aj -
  // 2 u_aj); minus the elastic force of Peer 2018 eq. 12 plus the penalty's gradient.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < slots; ++a) {
    Vec3 g = -stress_[a] * gradSum_[a];
    Vec3 gather = Vec3::Zero();
    for (std::size_t k = pairBegin_[a]; k < pairBegin_[a + 1]; ++k) {
      const auto j = static_cast<std::size_t>(pairSlot_[k]);
      gather += stress_[j] * pairGrad_[pairReverse_[k]];
      g += pairHourglass_[k] * ((defGrad_[a] + defGrad_[j]) * pairX_[k] - 2.0 * (u[j] - u[a]));
    }
    out[a] = g + volume_[a] * gather;
  }
}

void ElasticityPeer2018::buildPreconditioner(Real dt) {
  // Block Jacobi: m_a I + dt^2 times the diagonal block of the elastic Hessian from each
  // neighbour's strain (R_i [mu |g|^2 I + (mu + lambda) g g^T] R_i^T V_i V_a^2, g = g_ia) plus the
  // penalty's direct pair term. It omits the coupling through b_a (small inside the body), which
  // only costs iterations, never correctness: CG needs the preconditioner SPD, nothing more.
  const std::size_t slots = slotId_.size();
  const Real dt2 = dt * dt;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < slots; ++a) {
    Mat3 D = Mat3::Zero();
    Real pair = 0;
    for (std::size_t k = pairBegin_[a]; k < pairBegin_[a + 1]; ++k) {
      const auto i = static_cast<std::size_t>(pairSlot_[k]);
      const Vec3 g = rotation_[i] * pairGrad_[pairReverse_[k]];
      D +=
          volume_[i] * volume_[a] * volume_[a] *
          (mu_[i] * g.squaredNorm() * Mat3::Identity() + (mu_[i] + lambda_[i]) * g * g.transpose());
      pair += 2.0 * pairHourglass_[k];
    }
    D += pair * Mat3::Identity();
    precond_[a] = (mass_[a] * Mat3::Identity() + dt2 * D).inverse();
  }
}

void ElasticityPeer2018::applySystem(const std::vector<Vec3>& v, Real dt, std::vector<Vec3>& out) {
  energyGradient(v, false, out);  // H v
  const std::size_t slots = slotId_.size();
  const Real dt2 = dt * dt;
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s)
    out[s] = fixed_[s] ? Vec3::Zero() : Vec3(mass_[s] * v[s] + dt2 * out[s]);
}

void ElasticityPeer2018::apply(World& world, const StepContext& context) {
  const std::size_t slots = slotId_.size();
  if (slots == 0) return;
  const Real dt = context.dt;
  auto& p = world.particles;
  mapSlots(world);
  auto& rotation = p.fields.get<Mat3>(field::kElasticRotation);
  gatherSlots(world, rotation);

  // Elastic forces at the start-of-step positions; also updates the rotations.
  energyGradient(x_, true, grad_);
  stats_.elasticEnergy = reducer_.sum(slots, [&](std::size_t s) { return energy_[s]; });

  solveVelocities(dt);
  conserveBodyMomentum(world);

#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    const Index i = slotIndex_[s];
    p.v[i] = fixed_[s] ? Vec3::Zero() : v_[s];
    rotation[i] = rotation_[s];
  }
}

// Copies the particles' state into slot order and marks the bodies holding a fixed particle.
// Allocates nothing (the slot arrays are sized in attach()).
void ElasticityPeer2018::gatherSlots(const World& world, const std::vector<Mat3>& rotation) {
  const std::size_t slots = slotId_.size();
  const auto& p = world.particles;
  const auto& fixed = p.fields.get<std::int32_t>(field::kFixed);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    const Index i = slotIndex_[s];
    x_[s] = p.x[i];
    fixed_[s] = fixed[i];
    v_[s] = fixed_[s] ? Vec3::Zero() : p.v[i];
    mass_[s] = p.mass[i];
    rotation_[s] = rotation[i];
  }

  std::fill(bodyFixed_.begin(), bodyFixed_.end(), 0);
  for (std::size_t s = 0; s < slots; ++s)
    if (fixed_[s]) bodyFixed_[static_cast<std::size_t>(bodyOf_[s])] = 1;
}

// Solves for v_ and fills the solver statistics. Allocates nothing.
void ElasticityPeer2018::solveVelocities(Real dt) {
  const std::size_t slots = slotId_.size();
  // Backward Euler of the linearised system: (M + dt^2 H) v = M v* - dt grad E.
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s)
    rhs_[s] = fixed_[s] ? Vec3::Zero() : Vec3(mass_[s] * v_[s] - dt * grad_[s]);
  buildPreconditioner(dt);

  // Preconditioned CG, warm-started with v*.
  applySystem(v_, dt, ap_);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < slots; ++s) {
    r_[s] = rhs_[s] - ap_[s];
    z_[s] = precond_[s] * r_[s];
    p_[s] = z_[s];
  }
  const Real bNorm = std::sqrt(
      reducer_.sum(slots, [&](std::size_t s) { return rhs_[s].dot(precond_[s] * rhs_[s]); }));
  Real rz = reducer_.sum(slots, [&](std::size_t s) { return r_[s].dot(z_[s]); });
  const Real target = parameters_.solverTolerance * bNorm;
  int iteration = 0;
  while (std::sqrt(std::max(rz, 0.0)) > target && iteration < parameters_.maxSolverIterations) {
    applySystem(p_, dt, ap_);
    const Real pAp = reducer_.sum(slots, [&](std::size_t s) { return p_[s].dot(ap_[s]); });
    if (!(pAp > 0)) break;  // p = 0 (converged to round-off) or a non-SPD operator (a bug)
    const Real alpha = rz / pAp;
#pragma omp parallel for schedule(static)
    for (std::size_t s = 0; s < slots; ++s) {
      v_[s] += alpha * p_[s];
      r_[s] -= alpha * ap_[s];
      z_[s] = precond_[s] * r_[s];
    }
    const Real rzNew = reducer_.sum(slots, [&](std::size_t s) { return r_[s].dot(z_[s]); });
    const Real beta = rzNew / rz;
    rz = rzNew;
#pragma omp parallel for schedule(static)
    for (std::size_t s = 0; s < slots; ++s) p_[s] = z_[s] + beta * p_[s];
    ++iteration;
  }
  stats_.iterations = iteration;
  stats_.relativeResidual = bNorm > 0 ? std::sqrt(std::max(rz, 0.0)) / bNorm : 0.0;
  stats_.converged = std::sqrt(std::max(rz, 0.0)) <= target;
}

// The exact solution conserves each free body's momentum (the energy is translation invariant,
// so sum_s grad_s = 0 and H has the translations in its null space); the CG residual does not.
// Remove its momentum part with a uniform velocity shift per body without fixed particles.
// Allocates nothing.
void ElasticityPeer2018::conserveBodyMomentum(const World& world) {
  const auto& p = world.particles;
  for (std::size_t b = 0; b < bodyCount_; ++b) {
    if (bodyFixed_[b]) continue;
    Vec3 wanted = Vec3::Zero(), actual = Vec3::Zero();
    Real mass = 0;
    for (std::size_t s = bodyBegin_[b]; s < bodyBegin_[b + 1]; ++s) {
      const std::size_t t = bodySlots_[s];
      wanted += mass_[t] * p.v[slotIndex_[t]];
      actual += mass_[t] * v_[t];
      mass += mass_[t];
    }
    const Vec3 shift = (wanted - actual) / mass;
    for (std::size_t s = bodyBegin_[b]; s < bodyBegin_[b + 1]; ++s) v_[bodySlots_[s]] += shift;
  }
}

}  // namespace sim
