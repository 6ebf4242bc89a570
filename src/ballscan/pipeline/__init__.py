"""One image to its estimates: the estimator's stages, the results and their reports and plots."""
