//! Blade-element (strip) model of a two-bladed teetering gyroplane rotor driven by a polar
//! table: autorotation, cruise trim and takeoff.
