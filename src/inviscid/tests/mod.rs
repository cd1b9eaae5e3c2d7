//! Unit tests of the panel method's internals against XFOIL 6.99: the wake (XYWAKE) and the
//! source influence matrix (QDCALC).

mod source_influence;
mod support;
mod wake;
