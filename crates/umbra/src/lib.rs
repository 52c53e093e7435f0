//! Umbra facade (being written).
