// The staged ("direct") Johnson-Cook initial guess, from the data alone:
//  1. A, B, n from the reference curves (room temperature +- tolerance, rate at or below the
//     reference rate, where the rate and temperature factors are 1): A is the yield stress
//     extrapolated to eps_p = 0, chosen so that ln(sigma - A) against ln eps_p is the straightest
//     line (least squares in stress of A + B eps_p^n, B and n from the log-log regression (weighted
//     by (sigma - A)^2) at each trial A; golden-section search on A in [0.6, 1] x the smallest
//     reference stress); the 0.2 % offset stress is reported beside it;
//  2. C from the room-temperature curves above the reference rate: least squares in stress of
//     sigma = (A + B eps_p^n)(1 + C ln rate*)(1 - T*^m), closed form in C, with T the test's
//     temperature raised by adiabatic heating for adiabatic tests
//     (T = T0 + chi / (rho cp) int sigma d eps_p along the measured curve);
//  3. m from the curves above room temperature: least squares in stress over m (golden section);
//  stages 2 and 3 are repeated once (heating in stage 2 depends on m, hot high-rate tests in
//  stage 3 on C). A fixed parameter keeps its given value in every stage.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/material/elastic_plastic.hpp"
#include "pointdriver/fit/curve_model.hpp"
#include "pointdriver/fit/experiment_data.hpp"

namespace impact::pointdriver::fit {

struct Stage {
  std::string name;    ///< e.g. "1: A, B, n (reference curves)"
  std::string method;  ///< one line
  JcValues values{};   ///< all five after the stage
  int curves = 0;      ///< curves used
  int points = 0;      ///< points used
  double rms = 0.0;    ///< RMS stress misfit of the stage's own closed form on its points [Pa]
  std::string note;    ///< e.g. the 0.2 % offset stress, or why the stage was skipped
};

struct StagedGuess {
  JcValues values{};
  std::vector<Stage> stages;
};

/// `start` gives the values of fixed parameters and of any stage that has no data;
/// `adiabatic[i]` says whether experiment i is run adiabatically.
StagedGuess staged_guess(const std::vector<Experiment>& experiments,
                         const std::vector<bool>& adiabatic, const ElasticPlasticParams& material,
                         const JcValues& start, const std::array<bool, 5>& free,
                         double room_tolerance = 10.0);

}  // namespace impact::pointdriver::fit
