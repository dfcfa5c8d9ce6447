#pragma once
// Internal trim solvers shared by trim.cpp (Newton) and steady_turn.cpp (continuation in roll).
#include "analysis/trim.h"

namespace motostab::analysis::detail {

// Newton's method from `res` (a warm start when `warm`, else the default state) to the trim at `speed`
// (trim.cpp).
void solveTrim(const vehicle::VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm);

// A turn from `res` to opt.roll in roll steps at the fixed speed, then the turn with opt's condition; with
// `stepWithCondition` every step keeps opt's condition (e.g. hands-free turns followed in roll)
// (steady_turn.cpp).
void continueTurn(const vehicle::VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res,
                  bool stepWithCondition = false);

// Throws TrimError where a wheel's lowest point is above the ground by more than the trim's residual
// allows: an equilibrium with a wheel in the air is not a turn of the vehicle (steady_turn.cpp).
void checkWheelsOnGround(const vehicle::VehicleModel& model, double speed, const TrimOptions& opt, const TrimResult& res);

}  // namespace motostab::analysis::detail
