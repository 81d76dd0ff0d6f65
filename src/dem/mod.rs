//! The discrete-element ridge simulator (Hopkins 1994, "Dynamic Ridge Model").
