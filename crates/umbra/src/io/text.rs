//! Helpers shared by the readers: reading a file's bytes, decoding text
//! (UTF-8 only, a leading byte-order mark dropped), numbers that overflow
//! `f64`, and quoting of file content in one-line messages.

use crate::UmbraError;
use std::path::Path;

/// The UTF-8 byte-order mark, as a `char`.
pub(crate) const BOM: char = '\u{feff}';

/// Reads a file's bytes, naming the file on failure.
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>, UmbraError> {
    std::fs::read(path).map_err(|source| UmbraError::Io {
        file: path.display().to_string(),
        action: "read",
        source,
    })
}

/// Writes bytes to a file, naming the file on failure.
pub(crate) fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), UmbraError> {
    std::fs::write(path, bytes).map_err(|source| UmbraError::Io {
        file: path.display().to_string(),
        action: "write",
        source,
    })
}

/// The text of `bytes` as UTF-8 without a leading byte-order mark, or a
/// [`UmbraError::Malformed`] of `format` naming the line and byte offset of
/// the first invalid byte (UTF-16 text is named as such).
pub(crate) fn decode<'a>(
    bytes: &'a [u8],
    file: &str,
    format: &'static str,
) -> Result<&'a str, UmbraError> {
    let malformed = |message: String| UmbraError::Malformed {
        file: file.to_string(),
        format,
        message,
    };
    if bytes.starts_with(&[0xff, 0xfe]) || bytes.starts_with(&[0xfe, 0xff]) {
        return Err(malformed(
            "UTF-16 text (byte-order mark at the start); save the file as UTF-8".to_string(),
        ));
    }
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        malformed(format!(
            "line {line}: not UTF-8 text (invalid byte 0x{:02x} at offset {at})",
            bytes[at]
        ))
    })?;
    Ok(strip_bom(text))
}

/// `text` without a leading UTF-8 byte-order mark.
pub(crate) fn strip_bom(text: &str) -> &str {
    text.strip_prefix(BOM).unwrap_or(text)
}

/// Parses a decimal number. A literal that is finite as written but too
/// large for `f64` (`1e400`) is an error saying so, rather than the
/// infinity the standard parser returns; `inf`, `infinity` and `nan`
/// (any case, signed) are returned as they are, for the coordinate check
/// to name.
pub(crate) fn parse_number(token: &str) -> Result<f64, String> {
    let value: f64 = token
        .parse()
        .map_err(|_| format!("'{}' is not a number", shorten(token)))?;
    if value.is_infinite() && !is_infinity_literal(token) {
        return Err(overflow_message(token));
    }
    Ok(value)
}

/// The message for a decimal literal beyond the range of `f64`.
pub(crate) fn overflow_message(token: &str) -> String {
    format!(
        "'{}' overflows f64 (beyond ±1.8e308, so not finite)",
        shorten(token)
    )
}

/// `true` if `token` spells infinity (`inf`, `-Infinity`, ...).
pub(crate) fn is_infinity_literal(token: &str) -> bool {
    let t = token.trim_start_matches(['+', '-']);
    t.eq_ignore_ascii_case("inf") || t.eq_ignore_ascii_case("infinity")
}

/// At most 32 characters of `s` for a message, with control and invisible
/// characters (a byte-order mark, say) escaped so that the message shows
/// what is there.
pub(crate) fn shorten(s: &str) -> String {
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i == 32 {
            out.push_str("...");
            break;
        }
        if c.is_control() || c == BOM || c == '\u{200b}' || c == '\u{a0}' {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

/// Appends the shortest decimal that reads back as the same `f64`: plain
/// notation for moderate magnitudes, exponent notation for very large or
/// small ones.
pub(crate) fn push_f64(out: &mut String, v: f64) {
    use std::fmt::Write as _;
    let a = v.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || (1.0e-5..1.0e16).contains(&a) || !a.is_finite() {
        write!(out, "{v}")
    } else {
        write!(out, "{v:e}")
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overflow_is_named_and_infinity_literals_pass() {
        assert!(parse_number("1e400").unwrap_err().contains("overflows f64"));
        assert!(parse_number("-1E999").unwrap_err().contains("overflows"));
        assert!(parse_number("inf").unwrap().is_infinite());
        assert!(parse_number("-Infinity").unwrap().is_infinite());
        assert!(parse_number("NaN").unwrap().is_nan());
        assert_eq!(parse_number("1e-400").unwrap(), 0.0);
        assert!(parse_number("x")
            .unwrap_err()
            .contains("'x' is not a number"));
    }

    #[test]
    fn decoding_names_the_problem() {
        assert_eq!(decode(b"\xef\xbb\xbfv 1", "f", "OBJ").unwrap(), "v 1");
        let e = decode(b"v 0\nv \xe9", "f.obj", "OBJ")
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "f.obj: malformed OBJ: line 2: not UTF-8 text (invalid byte 0xe9 at offset 6)"
        );
        let e = decode(b"\xff\xfev\x00", "f", "OFF")
            .unwrap_err()
            .to_string();
        assert!(e.contains("UTF-16"), "{e}");
    }

    #[test]
    fn numbers_round_trip_bit_for_bit() {
        for v in [
            0.1,
            -0.0,
            1.0 / 3.0,
            1e-300,
            5e-324,
            1e300,
            123456789012345680.0,
        ] {
            let mut s = String::new();
            push_f64(&mut s, v);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{s}");
        }
    }

    #[test]
    fn shorten_shows_invisible_characters() {
        assert_eq!(shorten("\u{feff}OFF"), "\\u{feff}OFF");
        assert_eq!(shorten(&"a".repeat(40)).len(), 35);
    }
}
