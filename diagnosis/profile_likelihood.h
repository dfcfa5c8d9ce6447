#pragma once
// 95 % profile-likelihood intervals of a fitted model's parameters: each parameter held at trial
// values, the others refitted (with the model's own noise held), the interval's ends where chi2 rises
// by 3.84, the chi-square(1) 95 % quantile (Venzon & Moolgavkar 1988, Applied Statistics 37:87; Pawitan
// 2001, In All Likelihood, sect. 3.4). An end that reaches a parameter's bound stays at the bound.
#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// Sets profileLow/High of every parameter of s.allParameters (s: the full fit of `model`, with
/// `problem` carrying that fit's noise). Where the Wald standard error is zero or not finite (a flat
/// likelihood: findings that all hold at the fit), the search steps out from 1 % of the parameter's range.
void calcProfiles(const FitProblem& problem, const ModelSpec& model, FitSummary& s);

/// The rise of chi2 over the fit s (of `model`, `problem` carrying its noise) with parameter `index`
/// held at `internalValue` (internal units: ln of a log-scale parameter) and the others refitted:
/// the profile deviance -2 ln(L_p(value) / L_max). Infinite where that value makes no valid vehicle.
double calcProfileRise(const FitProblem& problem, const ModelSpec& model, const FitSummary& s, int index,
                       double internalValue);

/// The chi-square(1) 95 % quantile: a profile rise above it puts the value outside the 95 % interval.
constexpr double kProfileChi2_95 = 3.841458820694124;

}  // namespace motostab::diagnosis
