//! LN kernels.
