#pragma once
// Volino's wrinkle height (Volino and Magnenat-Thalmann 1999, taken from
// cloth folds; survey §1.3.2, "Modèle géométrique"):
//   t = 2 lambda (1 / (1 + (l/L)^2) - 1) + 1
// with l and L the current and rest base lengths of the fold and lambda how
// compressed the rest state already is. t(0) = 1 and t(L) = 1 - lambda, and t
// decreases with l; the survey's "from 1 to 0" holds once t is clamped at 0.

namespace mq::optics {

// compression = l / L (>= 0). Returns t in [0, 1].
double volinoWrinkleHeight(double compression, double lambda);

}  // namespace mq::optics
