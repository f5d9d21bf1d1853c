//! What a subcommand hands back: text and JSON renderings, or a failure with its exit code.

use demcontact::Error;
use serde_json::{Value, json};

/// A successful result in both renderings.
pub struct Output {
    /// Human-readable text (ends with a newline).
    pub text: String,
    /// One JSON object.
    pub json: Value,
}

/// Why a command failed.
#[derive(Debug)]
pub enum Kind {
    /// The library refused the computation (exit 1).
    Refused(Error),
    /// Bad input file (exit 3).
    Input {
        file: String,
        line: usize,
        column: usize,
    },
    /// Output file not written (exit 4).
    Output { file: String },
    /// A value the command line may not take although it parses (exit 2, as clap's errors).
    Usage,
}

/// A failure: message and kind.
#[derive(Debug)]
pub struct Failure {
    /// One-line message.
    pub message: String,
    /// What failed.
    pub kind: Kind,
}

impl Failure {
    pub fn refused(message: String, e: Error) -> Self {
        Self {
            message,
            kind: Kind::Refused(e),
        }
    }

    pub fn input(file: &str, line: usize, column: usize, what: String) -> Self {
        let message = if line > 0 {
            format!("{file}:{line}:{column}: {what}")
        } else {
            format!("{file}: {what}")
        };
        Self {
            message,
            kind: Kind::Input {
                file: file.into(),
                line,
                column,
            },
        }
    }

    pub fn output(file: &str, what: String) -> Self {
        Self {
            message: format!("{file}: {what}"),
            kind: Kind::Output { file: file.into() },
        }
    }

    pub fn usage(message: String) -> Self {
        Self {
            message,
            kind: Kind::Usage,
        }
    }

    pub fn exit_code(&self) -> u8 {
        match self.kind {
            Kind::Refused(_) => 1,
            Kind::Usage => 2,
            Kind::Input { .. } => 3,
            Kind::Output { .. } => 4,
        }
    }

    pub fn to_json(&self) -> Value {
        let (kind, extra) = match &self.kind {
            Kind::Refused(e) => (
                "refused",
                json!({ "status": demcontact::ffi::dc_status::of(*e).code() }),
            ),
            Kind::Input { file, line, column } => (
                "input",
                json!({ "file": file, "line": line, "column": column }),
            ),
            Kind::Output { file } => ("output", json!({ "file": file })),
            Kind::Usage => ("usage", json!({})),
        };
        let mut err = serde_json::Map::new();
        err.insert("message".into(), json!(self.message));
        err.insert("exit_code".into(), json!(self.exit_code()));
        err.insert("kind".into(), json!(kind));
        if let Value::Object(m) = extra {
            err.extend(m);
        }
        json!({ "error": err })
    }
}

/// The library's message for an error (the C status message, without its NUL).
pub fn describe(e: Error) -> String {
    let code = demcontact::ffi::dc_status::of(e).code();
    let p = demcontact::ffi::status::dc_status_str(code);
    // SAFETY: dc_status_str returns a static NUL-terminated string, never NULL.
    let s = unsafe { std::ffi::CStr::from_ptr(p) };
    format!("{} (status {code})", s.to_string_lossy())
}

/// A number in JSON, or null when not finite (JSON has no NaN).
pub fn num(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}
