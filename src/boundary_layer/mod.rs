//! Integral boundary layer (Drela & Giles 1987; Drela 1989): closures with their partial
//! derivatives, e^n amplification and transition, and the discrete equations of one interval.
