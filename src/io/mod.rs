//! File input and output. Only this module touches NetCDF.

pub mod itd_netcdf;
