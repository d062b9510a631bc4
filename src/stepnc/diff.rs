//! Semantic difference of two STEP-NC files (placeholder replaced below).
