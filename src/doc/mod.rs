//! Guide pages: long-form documentation that does not belong to one item.
//!
//! * [`conventions`]: units, signs, names.

pub mod conventions;
