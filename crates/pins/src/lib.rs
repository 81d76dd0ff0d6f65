//! No code: this crate only names dependency features for the workspace's own builds
//! (its manifest says which and why), so that they share their artifacts.

#![warn(missing_docs)]
