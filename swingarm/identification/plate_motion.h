#pragma once
// Small rigid motion of the reference plate (plane x-z, displacement along y), its twist axis (the line
// dy = 0) and first-order uncertainty propagation. Shared by the static test and the modal (ODS) axes.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace motostab::swingarm::identification {

/// A point of the plate plane: x along the swingarm, z up, m.
struct PlatePoint {
  double x = 0, z = 0;
};

/// Empty if the points define a plane fit dy = d0 + dx x + dz z; otherwise the reason (fewer than three
/// points, or points (nearly) collinear: smallest/largest principal spread below 1e-3).
std::string checkPlaneGeometry(const std::vector<PlatePoint>& points);

/// Least-squares operator P (3 x n): [d0, dx, dz] = P * dy for displacements dy at `points`.
/// std::logic_error if checkPlaneGeometry fails (the test readers check it first).
Eigen::MatrixXd calcPlaneFitOperator(const std::vector<PlatePoint>& points);

/// Design matrix A (n x 3) of the plane model, rows [1, x, z].
Eigen::MatrixXd calcPlaneDesignMatrix(const std::vector<PlatePoint>& points);

/// Twist axis of a plane motion dy(x,z) = d0 + dx x + dz z (per unit load), seen from the force point.
/// The rotation vector is (omega_x, omega_z) = (-dz, dx); the axis direction e is oriented so that the
/// arm is positive, i.e. the motion at the force point is y = theta * arm (seed eq. 2).
struct TwistAxis {
  double rotation = 0;           ///< theta per unit load, rad (per N for a static test)
  double arm = 0;                ///< a: distance from the force point to the axis, m (seed eq. 2)
  double betaDeg = 0;            ///< beta: angle from the x axis to e, deg, in (-180, 180]
  double forcePointMotion = 0;   ///< |y| at the force point per unit load (m/N for a static test)
  Eigen::Vector2d point;         ///< foot of the perpendicular from the force point on the axis, (x, z) m
  Eigen::Vector2d direction;     ///< e = (e_x, e_z)
};

/// The axis dy = 0 of `plane` = [d0, dx, dz]. Throws io::ResultError for a pure translation.
TwistAxis calcTwistAxis(const Eigen::Vector3d& plane, const PlatePoint& forcePoint);

/// Lateral displacement y at `r` (per unit rotation) of a rotation about an axis through `point` with
/// direction angle betaDeg: y = e_z (x - p_x) - e_x (z - p_z).
double calcArmAt(const Eigen::Vector2d& point, double betaDeg, const PlatePoint& r);

/// First-order propagation: covariance of f(x) given the covariance of x, by central differences.
Eigen::MatrixXd propagateCovariance(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                    const Eigen::VectorXd& x, const Eigen::MatrixXd& covariance);

/// Wraps an angle difference to (-180, 180] deg.
double wrapDegrees(double angle);

}  // namespace motostab::swingarm::identification
