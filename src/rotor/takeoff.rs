//! Takeoff placeholder.
