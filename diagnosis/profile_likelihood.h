#pragma once
// 95 % profile-likelihood intervals of a fitted model's parameters: each parameter held at trial
// values, the others refitted (with the model's own noise held), the interval's ends where chi2 rises
// by 3.84, the chi-square(1) 95 % quantile (Venzon & Moolgavkar 1988, Applied Statistics 37:87; Pawitan
// 2001, In All Likelihood, sect. 3.4). An end that reaches a parameter's bound stays at the bound.
#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// Sets profileLow/High of every parameter of s.allParameters (s: the full fit of `model`, with
/// `problem` carrying that fit's noise).
void calcProfiles(const FitProblem& problem, const ModelSpec& model, FitSummary& s);

}  // namespace motostab::diagnosis
