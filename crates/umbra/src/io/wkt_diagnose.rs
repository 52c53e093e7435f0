//! A small structural check of WKT text that says what is wrong and where
//! when the `wkt` crate refuses a text (its messages, such as "Missing
//! closing parenthesis for type", often name an unrelated mistake), and
//! that finds decimal literals too large for `f64` (`1e400`), which the
//! crate would silently turn into infinity.
//!
//! The grammar checked: a geometry is a type keyword, optional `Z`/`M`/
//! `ZM`, then `EMPTY` or a parenthesised list nested as deep as the type
//! needs (`POINT`, `LINESTRING` and `MULTIPOINT` one level, `POLYGON`,
//! `MULTILINESTRING` and a `MULTIPOINT` of parenthesised points two,
//! `MULTIPOLYGON` three); a coordinate is 2 numbers, 3 with `Z` or `M`, 4
//! with `ZM`;
//! `GEOMETRYCOLLECTION` holds geometries. Nesting depth is bounded by the
//! caller's pre-scan, which bounds the recursion here.

use super::text::{is_infinity_literal, overflow_message, shorten};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Tok<'a> {
    Open,
    Close,
    Comma,
    Word(&'a str),
    Number(&'a str),
    End,
}

struct Lexer<'a> {
    text: &'a str,
    at: usize,
    /// Byte offset of the token last returned.
    start: usize,
    /// Numbers per coordinate of the geometry being read, once known.
    dims: Option<usize>,
}

impl<'a> Lexer<'a> {
    fn peek(&self) -> (Tok<'a>, usize) {
        let bytes = self.text.as_bytes();
        // Skip white space as `char::is_whitespace` sees it (the words
        // below end at the same characters, so every token is non-empty
        // and the lexer always advances).
        let i = self.text[self.at..]
            .find(|c: char| !c.is_whitespace())
            .map_or(self.text.len(), |k| self.at + k);
        if i >= bytes.len() {
            return (Tok::End, i);
        }
        let tok = match bytes[i] {
            b'(' => return (Tok::Open, i),
            b')' => return (Tok::Close, i),
            b',' => return (Tok::Comma, i),
            _ => {
                let end = self.text[i..]
                    .find(|c: char| c.is_whitespace() || matches!(c, '(' | ')' | ','))
                    .map_or(self.text.len(), |k| i + k);
                let word = &self.text[i..end];
                let first = word.chars().next().unwrap_or(' ');
                if first.is_alphabetic()
                    && !is_infinity_literal(word)
                    && !word.eq_ignore_ascii_case("nan")
                {
                    Tok::Word(word)
                } else {
                    Tok::Number(word)
                }
            }
        };
        (tok, i)
    }

    fn next(&mut self) -> Tok<'a> {
        let (tok, i) = self.peek();
        self.start = i;
        self.at = match tok {
            Tok::Open | Tok::Close | Tok::Comma => i + 1,
            Tok::Word(w) | Tok::Number(w) => i + w.len(),
            Tok::End => i,
        };
        tok
    }

    /// `line L, column C` of the last token.
    fn here(&self) -> String {
        super::wkt::position(self.text, self.start)
    }
}

fn describe(tok: Tok<'_>) -> String {
    match tok {
        Tok::Open => "'('".to_string(),
        Tok::Close => "')'".to_string(),
        Tok::Comma => "','".to_string(),
        Tok::Word(w) | Tok::Number(w) => format!("'{}'", shorten(w)),
        Tok::End => "the end of the text".to_string(),
    }
}

type Check = Result<(), String>;

/// The first literal in `text` that overflows `f64`, as a message.
pub(crate) fn find_overflow(text: &str) -> Option<String> {
    let mut lx = Lexer {
        text,
        at: 0,
        start: 0,
        dims: None,
    };
    loop {
        match lx.next() {
            Tok::End => return None,
            Tok::Number(n) => {
                if let Ok(v) = n.parse::<f64>() {
                    if v.is_infinite() && !is_infinity_literal(n) {
                        return Some(format!("{} at {}", overflow_message(n), lx.here()));
                    }
                }
            }
            _ => {}
        }
    }
}

/// What is structurally wrong with `text`, if this check finds it.
pub(crate) fn diagnose(text: &str) -> Option<String> {
    let mut lx = Lexer {
        text,
        at: 0,
        start: 0,
        dims: None,
    };
    geometry(&mut lx).err()
}

fn geometry(lx: &mut Lexer<'_>) -> Check {
    let tok = lx.next();
    let Tok::Word(kind) = tok else {
        return Err(format!(
            "expected a geometry type (POLYGON, MULTIPOLYGON, ...) at {}, found {}",
            lx.here(),
            describe(tok)
        ));
    };
    let upper = kind.to_ascii_uppercase();
    let depth = match upper.as_str() {
        "POINT" | "LINESTRING" | "MULTIPOINT" | "TRIANGLE" => 1,
        "POLYGON" | "MULTILINESTRING" => 2,
        "MULTIPOLYGON" => 3,
        "GEOMETRYCOLLECTION" => 0,
        _ => {
            return Err(format!(
                "unknown geometry type '{}' at {}",
                shorten(kind),
                lx.here()
            ))
        }
    };
    // Without `Z`, `M` or `ZM` a coordinate has two numbers.
    lx.dims = Some(2);
    if let (Tok::Word(w), _) = lx.peek() {
        if ["Z", "M", "ZM"].iter().any(|d| w.eq_ignore_ascii_case(d)) {
            lx.dims = Some(if w.len() == 2 { 4 } else { 3 });
            lx.next();
        }
    }
    match lx.peek().0 {
        Tok::Word(w) if w.eq_ignore_ascii_case("EMPTY") => {
            lx.next();
            return Ok(());
        }
        Tok::Open => {}
        other => {
            lx.next();
            return Err(format!(
                "expected '(' or EMPTY after {upper} at {}, found {}",
                lx.here(),
                describe(other)
            ));
        }
    }
    if depth == 0 {
        return list(lx, &mut |lx| geometry(lx), "a geometry");
    }
    // A MULTIPOINT may hold bare or parenthesised points.
    let depth = if upper == "MULTIPOINT" && lookahead_open_open(lx) {
        2
    } else {
        depth
    };
    nested(lx, depth, &upper)
}

fn lookahead_open_open(lx: &Lexer<'_>) -> bool {
    let mut copy = Lexer {
        text: lx.text,
        at: lx.at,
        start: lx.start,
        dims: None,
    };
    copy.next() == Tok::Open && copy.next() == Tok::Open
}

/// `( item {, item} )`, where an item may also be `EMPTY`.
fn list(lx: &mut Lexer<'_>, item: &mut dyn FnMut(&mut Lexer<'_>) -> Check, what: &str) -> Check {
    let tok = lx.next();
    if tok != Tok::Open {
        return Err(format!(
            "expected '(' at {}, found {}",
            lx.here(),
            describe(tok)
        ));
    }
    loop {
        match lx.peek().0 {
            Tok::Word(w) if w.eq_ignore_ascii_case("EMPTY") && what != "a geometry" => {
                lx.next();
            }
            Tok::Comma | Tok::Close | Tok::End => {
                let tok = lx.next();
                return Err(format!(
                    "expected {what} at {}, found {}",
                    lx.here(),
                    describe(tok)
                ));
            }
            _ => item(lx)?,
        }
        match lx.next() {
            Tok::Comma => {}
            Tok::Close => return Ok(()),
            tok => {
                return Err(format!(
                    "expected ',' or ')' after {what} at {}, found {} (a missing comma?)",
                    lx.here(),
                    describe(tok)
                ))
            }
        }
    }
}

fn nested(lx: &mut Lexer<'_>, depth: usize, kind: &str) -> Check {
    if depth == 1 {
        return list(lx, &mut coordinate, "a coordinate");
    }
    let what = match depth {
        2 if kind == "POLYGON" || kind == "MULTIPOLYGON" => "a ring in parentheses",
        2 => "a list of coordinates in parentheses",
        _ => "a polygon in parentheses",
    };
    list(
        lx,
        &mut |lx| {
            if lx.peek().0 != Tok::Open {
                let tok = lx.next();
                return Err(format!(
                    "expected {what} at {}, found {} ({kind} needs {} levels of parentheses)",
                    lx.here(),
                    describe(tok),
                    depth_of(kind)
                ));
            }
            nested(lx, depth - 1, kind)
        },
        what,
    )
}

fn depth_of(kind: &str) -> usize {
    match kind {
        "POLYGON" | "MULTILINESTRING" => 2,
        "MULTIPOLYGON" => 3,
        _ => 1,
    }
}

/// 2 to 4 numbers.
fn coordinate(lx: &mut Lexer<'_>) -> Check {
    let mut n = 0;
    while let (Tok::Number(_) | Tok::Word(_), _) = lx.peek() {
        let tok = lx.next();
        if let Tok::Word(w) | Tok::Number(w) = tok {
            if w.parse::<f64>().is_err() {
                return Err(format!("'{}' at {} is not a number", shorten(w), lx.here()));
            }
        }
        n += 1;
    }
    if !(2..=4).contains(&n) {
        return Err(format!(
            "a coordinate of {n} number(s) ending at {}: expected 2 (x y), or 3 or 4 with Z/M",
            lx.here()
        ));
    }
    match lx.dims {
        Some(d) if d != n => Err(format!(
            "a coordinate of {n} numbers ending at {}, but this geometry's coordinates have {d}{}",
            lx.here(),
            if d == 2 {
                " (x y z or x y z m need the Z, M or ZM keyword: POLYGON Z (...))"
            } else {
                ""
            }
        )),
        Some(_) => Ok(()),
        None => {
            lx.dims = Some(n);
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mistakes_are_named_where_they_are() {
        let cases = [
            ("POLYGON ((0 0, 1 0, 1 x, 0 0))", "'x' at line 1, column 23 is not a number"),
            ("POLYGON ((0 0, 1 0 1 1, 0 0))", "a coordinate of 4 numbers ending at line 1, column 22, but this geometry's coordinates have 2"),
            ("POLYGON ((0 0, 1 0, , 0 0))", "expected a coordinate at line 1, column 21, found ','"),
            ("POLYGN ((0 0, 1 0, 1 1, 0 0))", "unknown geometry type 'POLYGN'"),
            ("POLYGON ((0 0, 1 0, 1 1, 0 0),)", "expected a ring in parentheses at line 1, column 31, found ')'"),
            ("POLYGON (0 0, 1 0, 1 1, 0 0)", "POLYGON needs 2 levels"),
            ("POLYGON ((0 0, 1 0, 1 1, 0 0) (1 1, 2 2, 1 2, 1 1))", "a missing comma?"),
            ("POLYGON ((0 0; 1 0, 1 1, 0 0))", "'0;' at line 1, column 13 is not a number"),
            ("POLYGON ((0 0, 1, 1 1, 0 0))", "a coordinate of 1 number(s)"),
        ];
        for (text, want) in cases {
            let got = diagnose(text).unwrap_or_default();
            assert!(got.contains(want), "{text}: {got}");
        }
        for good in [
            "POLYGON ((0 0, 1 0, 1 1, 0 0), (0.1 0.1, 0.2 0.1, 0.1 0.2, 0.1 0.1))",
            "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), EMPTY)",
            "GEOMETRYCOLLECTION (POINT (1 2), MULTIPOINT ((1 2), (3 4)), MULTIPOINT (1 2, 3 4))",
            "POLYGON Z ((0 0 0, 1 0 0, 1 1 0, 0 0 0))",
            "POLYGON EMPTY",
            "POLYGON ((0 0, NaN 0, inf 1, 0 0))",
        ] {
            assert_eq!(diagnose(good), None, "{good}");
        }
    }

    #[test]
    fn unicode_white_space_ends_the_text_scan() {
        // Found by the read_wkt fuzz target: a no-break space (U+00A0)
        // once stopped the lexer from advancing.
        for text in [
            "POLYGON\u{a0}((0 0, 1 0, 1 1, 0 0))",
            "\u{2003}",
            "1\u{85}2",
        ] {
            let _ = diagnose(text);
            assert_eq!(find_overflow(text), None, "{text:?}");
        }
    }

    #[test]
    fn overflowing_literals_are_found() {
        assert_eq!(
            find_overflow("POLYGON ((0 0, 1e400 0, 1 1, 0 0))").unwrap(),
            "'1e400' overflows f64 (beyond ±1.8e308, so not finite) at line 1, column 16"
        );
        assert_eq!(find_overflow("POLYGON ((0 0, inf 0, 1e308 1, 0 0))"), None);
    }
}
