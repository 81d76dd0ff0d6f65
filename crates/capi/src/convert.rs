//! Library errors to status codes and messages.

use super::{
    FfiError, PRESSRIDGE_ERR_BAD_SIZE, PRESSRIDGE_ERR_BAD_VALUE, PRESSRIDGE_ERR_IO,
    PRESSRIDGE_ERR_NOT_FINITE, PRESSRIDGE_ERR_NOT_FOUND, PRESSRIDGE_ERR_NUMERICAL,
    PRESSRIDGE_ERR_PARSE,
};
use pressridge::io::itd_netcdf::NetcdfError;
use pressridge::itd::{ColumnError, ItdError};
use pressridge::scene::SceneError;
use pressridge::table::lookup::LookupError;

fn column_code(e: &ColumnError) -> i32 {
    match e {
        ColumnError::NotFinite { .. } | ColumnError::TracerNotFinite { .. } => {
            PRESSRIDGE_ERR_NOT_FINITE
        }
        ColumnError::Negative { .. }
        | ColumnError::TooThick { .. }
        | ColumnError::CfOutOfRange { .. }
        | ColumnError::AreaSum { .. }
        | ColumnError::IceAreaAboveOne { .. }
        | ColumnError::AreaTooLarge { .. } => PRESSRIDGE_ERR_BAD_VALUE,
        ColumnError::NoConvergence { .. }
        | ColumnError::OpenWaterExhausted { .. }
        | ColumnError::StepFailed { .. }
        | ColumnError::Unphysical { .. } => PRESSRIDGE_ERR_NUMERICAL,
    }
}

impl From<ItdError> for FfiError {
    fn from(e: ItdError) -> Self {
        let (code, column) = match &e {
            ItdError::Column { column, source } => (column_code(source), Some(*column)),
            ItdError::Shape { .. } => (PRESSRIDGE_ERR_BAD_SIZE, None),
            ItdError::Parameter { value, .. } if !value.is_finite() => {
                (PRESSRIDGE_ERR_NOT_FINITE, None)
            }
            ItdError::Bounds(_)
            | ItdError::Parameter { .. }
            | ItdError::CfTable(_)
            | ItdError::MuRdgTable(_)
            | ItdError::Layout(_) => (PRESSRIDGE_ERR_BAD_VALUE, None),
        };
        let mut message = e.to_string();
        if let Some(c) = column {
            message.push_str(&format!(
                " (column index {c} counts from 0: Fortran column {})",
                c + 1
            ));
        }
        FfiError {
            code,
            message,
            column,
        }
    }
}

impl From<NetcdfError> for FfiError {
    fn from(e: NetcdfError) -> Self {
        FfiError::new(PRESSRIDGE_ERR_IO, e.to_string())
    }
}

impl From<SceneError> for FfiError {
    fn from(e: SceneError) -> Self {
        let code = match &e {
            SceneError::Parse(_) | SceneError::Override(..) => PRESSRIDGE_ERR_PARSE,
            SceneError::Invalid(..) | SceneError::World(_) => PRESSRIDGE_ERR_BAD_VALUE,
        };
        FfiError::new(code, e.to_string())
    }
}

impl From<LookupError> for FfiError {
    fn from(e: LookupError) -> Self {
        let code = match &e {
            LookupError::UnknownField { .. } => PRESSRIDGE_ERR_NOT_FOUND,
            LookupError::Set { .. } => PRESSRIDGE_ERR_BAD_VALUE,
            LookupError::NotFinite { .. } => PRESSRIDGE_ERR_NOT_FINITE,
            LookupError::Invalid(_) => PRESSRIDGE_ERR_BAD_VALUE,
            LookupError::Friction { .. } | LookupError::NoFriction => PRESSRIDGE_ERR_NOT_FOUND,
        };
        FfiError::new(code, e.to_string())
    }
}
