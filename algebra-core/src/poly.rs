//! Placeholder: the sparse multivariate polynomial scalar arrives in this commit series.
