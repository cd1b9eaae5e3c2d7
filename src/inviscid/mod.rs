//! Inviscid flow: linear-vorticity stream-function panel method (Drela 1989), unit solutions
//! for α = 0° and 90°, source-panel influence for the viscous coupling, Karman–Tsien
//! compressibility.
