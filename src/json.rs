//! A strict, bounded JSON reader (RFC 8259) for everything lncert reads from
//! users and certificates.
//!
//! `serde_json` keeps the *last* of two equal keys and builds its whole tree
//! before anyone can look at its size. Neither is acceptable for a public
//! statement such as a certificate, so shapes, curves and certificates are read
//! here instead:
//!
//! - **duplicate keys are rejected** at every level, with the key's path;
//! - **limits are checked while parsing**, before memory is spent: total bytes,
//!   nesting depth, total nodes (values), and characters per string and per
//!   number token ([`Limits`]);
//! - numbers are kept as their exact text (never read through `f64`);
//! - nothing else is lenient: no comments, no trailing commas, no control
//!   characters in strings, no lone surrogates, no text after the value.
//!
//! Work and memory are linear in the input: every byte is looked at a bounded
//! number of times, and a node costs at most a few dozen bytes: a value is 24
//! bytes, an object member 40 (its key a slice of the text, decoded only when
//! it holds an escape). Numbers, keys and strings without escapes are slices of
//! the text (no copy); each array and object is allocated once, at its exact
//! size.

use std::borrow::Cow;
use std::fmt;

/// Limits of the reader, checked while parsing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest input, in bytes.
    pub max_bytes: usize,
    /// Deepest nesting of arrays and objects.
    pub max_depth: usize,
    /// Most values (objects, arrays, strings, numbers, literals) in the document.
    pub max_nodes: usize,
    /// Longest string, in bytes after unescaping.
    pub max_string_bytes: usize,
    /// Longest number token, in bytes.
    pub max_number_bytes: usize,
}

impl Limits {
    /// The limits of every lncert input: 128 MiB, depth 32, 8 Mi values,
    /// strings up to 1 MB (SVG path data), numbers up to 4 096 characters.
    pub const DEFAULT: Limits = Limits {
        max_bytes: 128 << 20,
        max_depth: 32,
        max_nodes: 8 << 20,
        max_string_bytes: 1_000_000,
        max_number_bytes: 4096,
    };
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

/// An object's key: its text between the quotes, as written (escapes
/// included), so that a member costs no allocation. Compared and shown
/// decoded: the key written `"a\u0062"` has the raw text `a\u0062` and the
/// text `ab`, and `get("ab")` finds it (unit test
/// `escaped_keys_are_compared_decoded`).
#[derive(Clone, Copy, Debug, Eq)]
pub struct Key<'a>(&'a str);

impl<'a> Key<'a> {
    /// The key as written in the document (escapes not decoded).
    pub fn raw(&self) -> &'a str {
        self.0
    }
    /// The key decoded (borrowed from the text when it has no escape).
    pub fn text(&self) -> Cow<'a, str> {
        if self.0.contains('\\') {
            Cow::Owned(unescape(self.0))
        } else {
            Cow::Borrowed(self.0)
        }
    }
}

impl PartialEq for Key<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.0 == other.0 || self.text() == other.text()
    }
}

impl PartialEq<str> for Key<'_> {
    fn eq(&self, other: &str) -> bool {
        self.text() == other
    }
}

impl PartialEq<&str> for Key<'_> {
    fn eq(&self, other: &&str) -> bool {
        *self == **other
    }
}

impl fmt::Display for Key<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text())
    }
}

/// Decodes the escapes of a string's text that the parser has validated.
fn unescape(raw: &str) -> String {
    let quoted = format!("\"{raw}\"");
    let lim = Limits {
        max_string_bytes: usize::MAX,
        ..Limits::DEFAULT
    };
    // the text was read by `string` once already: decoding it again cannot fail
    match Parser::new(&quoted, &lim).string() {
        Ok(s) => s.into_owned(),
        Err(_) => raw.to_string(),
    }
}

/// A JSON value, borrowing its numbers, keys and strings from the document's
/// text (only a string with an escape is copied); object members keep their
/// order and are unique.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Json<'a> {
    /// `null`
    Null,
    /// `true` / `false`
    Bool(bool),
    /// A number, as its exact text (`-0.5e3`).
    Number(&'a str),
    /// A string, unescaped.
    String(Cow<'a, str>),
    /// An array.
    Array(Box<[Json<'a>]>),
    /// An object: its members in document order, keys unique.
    Object(Box<[(Key<'a>, Json<'a>)]>),
}

impl<'a> Json<'a> {
    /// The member `key` of an object.
    pub fn get(&self, key: &str) -> Option<&Json<'a>> {
        match self {
            Json::Object(m) => m.iter().find(|(k, _)| *k == key).map(|(_, v)| v),
            _ => None,
        }
    }
    /// The string, if this is one.
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Json::String(s) => Some(s),
            _ => None,
        }
    }
    /// The elements, if this is an array.
    pub fn as_array(&self) -> Option<&[Json<'a>]> {
        match self {
            Json::Array(a) => Some(a),
            _ => None,
        }
    }
    /// The members, if this is an object.
    pub fn as_object(&self) -> Option<&[(Key<'a>, Json<'a>)]> {
        match self {
            Json::Object(m) => Some(m),
            _ => None,
        }
    }
    /// A short description for error messages (`a string`, `an array of 3 elements`).
    pub fn describe(&self) -> String {
        match self {
            Json::Null => "null".to_string(),
            Json::Bool(_) => "a boolean".to_string(),
            Json::Number(_) => "a number".to_string(),
            Json::String(_) => "a string".to_string(),
            Json::Array(a) => format!("an array of {} elements", a.len()),
            Json::Object(_) => "an object".to_string(),
        }
    }
    /// The same document as a `serde_json` value (numbers keep their exact text).
    pub fn to_value(&self) -> serde_json::Value {
        use serde_json::Value;
        match self {
            Json::Null => Value::Null,
            Json::Bool(b) => Value::Bool(*b),
            // the token was validated by the grammar, which serde_json shares
            Json::Number(n) => serde_json::from_str::<serde_json::Number>(n)
                .map(Value::Number)
                .unwrap_or(Value::Null),
            Json::String(s) => Value::String(s.to_string()),
            Json::Array(a) => Value::Array(a.iter().map(Json::to_value).collect()),
            Json::Object(m) => Value::Object(
                m.iter()
                    .map(|(k, v)| (k.text().into_owned(), v.to_value()))
                    .collect(),
            ),
        }
    }
}

/// Why a document was rejected: where (a field path such as `a.arc.center[1]`,
/// and the line and column) and why.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct JsonError {
    /// Path of the value being read (`(top level)` outside any value).
    pub path: String,
    /// 1-based line of the offending byte.
    pub line: usize,
    /// 1-based column (in bytes) of the offending byte.
    pub column: usize,
    /// What is wrong.
    pub reason: String,
    /// Which kind of problem.
    pub kind: ErrorKind,
}

/// The kinds of [`JsonError`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// Not JSON (RFC 8259), or not UTF-8.
    Syntax,
    /// Over one of the [`Limits`].
    Limit,
    /// A key given twice in one object.
    Duplicate,
}

impl fmt::Display for JsonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} (line {}, column {}): {}",
            self.path, self.line, self.column, self.reason
        )
    }
}

enum Seg<'a> {
    Key(&'a str),
    Index(usize),
}

struct Parser<'a> {
    text: &'a str,
    b: &'a [u8],
    pos: usize,
    nodes: usize,
    lim: Limits,
    path: Vec<Seg<'a>>,
    /// The elements of the arrays and members of the objects being read,
    /// innermost last: each array or object is moved out in one allocation
    /// of its exact size when it closes (no growth, no shrinking).
    items: Vec<Json<'a>>,
    members: Vec<(Key<'a>, Json<'a>)>,
}

/// The parser's results: the error boxed, so that a `Result` moves as
/// cheaply as the value it carries (every value read is returned through one).
type Parsed<T> = Result<T, Box<JsonError>>;

/// Reads one JSON document under `limits`.
pub fn parse<'a>(text: &'a str, limits: &Limits) -> Result<Json<'a>, JsonError> {
    parse_boxed(text, limits).map_err(|e| *e)
}

fn parse_boxed<'a>(text: &'a str, limits: &Limits) -> Parsed<Json<'a>> {
    let mut p = Parser::new(text, limits);
    if text.len() > limits.max_bytes {
        return Err(p.limit(format!(
            "the document has {} bytes, more than the limit of {}",
            text.len(),
            limits.max_bytes
        )));
    }
    p.ws();
    let v = p.value(0)?;
    p.ws();
    if p.pos < p.b.len() {
        return Err(p.err("text after the JSON value"));
    }
    Ok(v)
}

/// 1-based line and column (in bytes) of byte `pos` of `bytes`.
fn line_col(bytes: &[u8], pos: usize) -> (usize, usize) {
    let upto = &bytes[..pos.min(bytes.len())];
    let line = 1 + upto.iter().filter(|&&c| c == b'\n').count();
    let column = 1 + upto.iter().rev().take_while(|&&c| c != b'\n').count();
    (line, column)
}

impl<'a> Parser<'a> {
    fn new(text: &'a str, limits: &Limits) -> Parser<'a> {
        Parser {
            text,
            b: text.as_bytes(),
            pos: 0,
            nodes: 0,
            lim: *limits,
            path: Vec::new(),
            items: Vec::new(),
            members: Vec::new(),
        }
    }

    fn path_string(&self) -> String {
        if self.path.is_empty() {
            return "(top level)".to_string();
        }
        let mut s = String::new();
        for seg in &self.path {
            match seg {
                Seg::Key(k) => {
                    if !s.is_empty() {
                        s.push('.');
                    }
                    s.push_str(k);
                }
                Seg::Index(i) => s.push_str(&format!("[{i}]")),
            }
        }
        s
    }

    fn err(&self, reason: impl Into<String>) -> Box<JsonError> {
        self.err_of(ErrorKind::Syntax, reason)
    }

    fn limit(&self, reason: impl Into<String>) -> Box<JsonError> {
        self.err_of(ErrorKind::Limit, reason)
    }

    fn err_of(&self, kind: ErrorKind, reason: impl Into<String>) -> Box<JsonError> {
        let (line, column) = line_col(self.b, self.pos);
        Box::new(JsonError {
            path: self.path_string(),
            line,
            column,
            reason: reason.into(),
            kind,
        })
    }

    /// Moves past the characters a string holds as they are (up to a quote,
    /// a backslash, a control character or the end).
    fn plain_run(&mut self) {
        let rest = &self.b[self.pos..];
        self.pos += rest
            .iter()
            .position(|&c| c == b'"' || c == b'\\' || c < 0x20)
            .unwrap_or(rest.len());
    }

    fn peek(&self) -> Option<u8> {
        self.b.get(self.pos).copied()
    }

    fn ws(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.pos += 1;
        }
    }

    fn node(&mut self) -> Parsed<()> {
        self.nodes += 1;
        if self.nodes > self.lim.max_nodes {
            return Err(self.limit(format!(
                "more than {} values in the document",
                self.lim.max_nodes
            )));
        }
        Ok(())
    }

    fn value(&mut self, depth: usize) -> Parsed<Json<'a>> {
        self.node()?;
        match self.peek() {
            None => Err(self.err("unexpected end of the document")),
            Some(b'{') => self.object(depth + 1),
            Some(b'[') => self.array(depth + 1),
            Some(b'"') => Ok(Json::String(self.string()?)),
            Some(b'-' | b'0'..=b'9') => self.number(),
            Some(b't') => self.literal("true", Json::Bool(true)),
            Some(b'f') => self.literal("false", Json::Bool(false)),
            Some(b'n') => self.literal("null", Json::Null),
            Some(c) => Err(self.err(format!("unexpected character {:?}", self.char_at(c)))),
        }
    }

    fn char_at(&self, c: u8) -> String {
        self.text
            .get(self.pos..)
            .and_then(|s| s.chars().next())
            .map(|ch| ch.to_string())
            .unwrap_or_else(|| format!("\\x{c:02x}"))
    }

    fn literal(&mut self, word: &str, v: Json<'a>) -> Parsed<Json<'a>> {
        if self.b[self.pos..].starts_with(word.as_bytes()) {
            self.pos += word.len();
            Ok(v)
        } else {
            Err(self.err(format!("expected `{word}`")))
        }
    }

    fn enter(&self, depth: usize) -> Parsed<()> {
        if depth > self.lim.max_depth {
            return Err(self.limit(format!(
                "nested deeper than the limit of {}",
                self.lim.max_depth
            )));
        }
        Ok(())
    }

    fn array(&mut self, depth: usize) -> Parsed<Json<'a>> {
        self.enter(depth)?;
        self.pos += 1;
        self.ws();
        if self.peek() == Some(b']') {
            self.pos += 1;
            return Ok(Json::Array(Box::new([])));
        }
        let base = self.items.len();
        loop {
            self.ws();
            self.path.push(Seg::Index(self.items.len() - base));
            let v = self.value(depth)?;
            self.path.pop();
            self.items.push(v);
            self.ws();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b']') => {
                    self.pos += 1;
                    return Ok(Json::Array(self.items.drain(base..).collect()));
                }
                _ => return Err(self.err("expected `,` or `]` in an array")),
            }
        }
    }

    fn object(&mut self, depth: usize) -> Parsed<Json<'a>> {
        self.enter(depth)?;
        self.pos += 1;
        // built only for an object past 16 members (the hasher's seed is not free)
        let mut seen: Option<std::collections::HashSet<Cow<'a, str>>> = None;
        self.ws();
        if self.peek() == Some(b'}') {
            self.pos += 1;
            return Ok(Json::Object(Box::new([])));
        }
        let base = self.members.len();
        loop {
            self.ws();
            if self.peek() != Some(b'"') {
                return Err(self.err("expected a key (a string) in an object"));
            }
            let key_start = self.pos;
            let decoded = self.string()?;
            let key = Key(&self.text[key_start + 1..self.pos - 1]);
            // the key's own text for the path: escaped keys are not shown
            let key_ref: &'a str = match &decoded {
                Cow::Borrowed(raw) => raw,
                Cow::Owned(_) => "(escaped key)",
            };
            self.path.push(Seg::Key(key_ref));
            // a linear scan while the object is small (every lncert format has
            // a handful of members), a hash set beyond: linear overall
            let members = &self.members[base..];
            let dup = if members.len() < 16 {
                members.iter().any(|(k, _)| *k == *decoded)
            } else {
                !seen
                    .get_or_insert_with(|| members.iter().map(|(k, _)| k.text()).collect())
                    .insert(decoded.clone())
            };
            if dup {
                self.pos = key_start;
                return Err(self.err_of(
                    ErrorKind::Duplicate,
                    format!("duplicate key \"{decoded}\": a document must say each thing once"),
                ));
            }
            self.ws();
            if self.peek() != Some(b':') {
                return Err(self.err("expected `:` after a key"));
            }
            self.pos += 1;
            self.ws();
            let v = self.value(depth)?;
            self.path.pop();
            self.members.push((key, v));
            self.ws();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b'}') => {
                    self.pos += 1;
                    return Ok(Json::Object(self.members.drain(base..).collect()));
                }
                _ => return Err(self.err("expected `,` or `}` in an object")),
            }
        }
    }

    fn string(&mut self) -> Parsed<Cow<'a, str>> {
        self.pos += 1; // opening quote
                       // without an escape, the string is a slice of the text
        let first = self.pos;
        self.plain_run();
        if self.peek() == Some(b'"') {
            if self.pos - first > self.lim.max_string_bytes {
                return Err(self.limit(format!(
                    "a string longer than the limit of {} bytes",
                    self.lim.max_string_bytes
                )));
            }
            self.pos += 1;
            return Ok(Cow::Borrowed(&self.text[first..self.pos - 1]));
        }
        self.pos = first;
        let mut out = String::new();
        loop {
            let start = self.pos;
            self.plain_run();
            out.push_str(&self.text[start..self.pos]);
            if out.len() > self.lim.max_string_bytes {
                return Err(self.limit(format!(
                    "a string longer than the limit of {} bytes",
                    self.lim.max_string_bytes
                )));
            }
            match self.peek() {
                None => return Err(self.err("unterminated string")),
                Some(b'"') => {
                    self.pos += 1;
                    return Ok(Cow::Owned(out));
                }
                Some(b'\\') => {
                    self.pos += 1;
                    let c = self.peek().ok_or_else(|| self.err("unterminated escape"))?;
                    self.pos += 1;
                    let ch = match c {
                        b'"' => '"',
                        b'\\' => '\\',
                        b'/' => '/',
                        b'b' => '\u{8}',
                        b'f' => '\u{c}',
                        b'n' => '\n',
                        b'r' => '\r',
                        b't' => '\t',
                        b'u' => self.unicode_escape()?,
                        _ => return Err(self.err("invalid escape in a string")),
                    };
                    out.push(ch);
                }
                Some(_) => return Err(self.err("control character in a string (escape it)")),
            }
        }
    }

    fn hex4(&mut self) -> Parsed<u32> {
        let h = self
            .text
            .get(self.pos..self.pos + 4)
            .filter(|h| h.bytes().all(|c| c.is_ascii_hexdigit()))
            .ok_or_else(|| self.err("expected four hex digits after \\u"))?;
        let v = u32::from_str_radix(h, 16).map_err(|_| self.err("bad \\u escape"))?;
        self.pos += 4;
        Ok(v)
    }

    fn unicode_escape(&mut self) -> Parsed<char> {
        let hi = self.hex4()?;
        let code = if (0xD800..0xDC00).contains(&hi) {
            if !self.b[self.pos..].starts_with(b"\\u") {
                return Err(self.err("lone surrogate in a \\u escape"));
            }
            self.pos += 2;
            let lo = self.hex4()?;
            if !(0xDC00..0xE000).contains(&lo) {
                return Err(self.err("lone surrogate in a \\u escape"));
            }
            0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)
        } else {
            hi
        };
        char::from_u32(code).ok_or_else(|| self.err("lone surrogate in a \\u escape"))
    }

    fn number(&mut self) -> Parsed<Json<'a>> {
        let start = self.pos;
        let digits = |p: &mut Self| {
            let s = p.pos;
            while matches!(p.peek(), Some(b'0'..=b'9')) {
                p.pos += 1;
            }
            p.pos - s
        };
        if self.peek() == Some(b'-') {
            self.pos += 1;
        }
        match self.peek() {
            Some(b'0') => self.pos += 1,
            Some(b'1'..=b'9') => {
                digits(self);
            }
            _ => return Err(self.err("a number needs digits")),
        }
        if self.peek() == Some(b'.') {
            self.pos += 1;
            if digits(self) == 0 {
                return Err(self.err("a number needs digits after `.`"));
            }
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if digits(self) == 0 {
                return Err(self.err("a number needs digits in its exponent"));
            }
        }
        if self.pos - start > self.lim.max_number_bytes {
            self.pos = start;
            return Err(self.limit(format!(
                "a number longer than the limit of {} characters",
                self.lim.max_number_bytes
            )));
        }
        Ok(Json::Number(&self.text[start..self.pos]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> Result<Json<'_>, JsonError> {
        parse(s, &Limits::DEFAULT)
    }

    #[test]
    fn reads_the_grammar() {
        let text = r#" {"a": [1, -0.5e+3, true, false, null, "x\"\u00e9\ud83d\ude00"], "b": {}} "#;
        let v = p(text).unwrap();
        let a = v.get("a").unwrap().as_array().unwrap();
        assert_eq!(a[1], Json::Number("-0.5e+3"));
        assert_eq!(a[5].as_str(), Some("x\"é😀"));
        // borrowed from the text unless an escape had to be decoded
        assert!(matches!(a[5], Json::String(Cow::Owned(_))));
        let plain = p(r#"{"key": "a/b"}"#).unwrap();
        assert!(matches!(
            plain.get("key"),
            Some(Json::String(Cow::Borrowed("a/b")))
        ));
        assert_eq!(v.get("b"), Some(&Json::Object(Box::new([]))));
        let serde: serde_json::Value = serde_json::from_str(text).unwrap();
        assert_eq!(v.to_value(), serde);
    }

    #[test]
    fn rejects_what_json_does_not_allow() {
        for bad in [
            "",
            "{",
            "[1,]",
            "{\"a\":1,}",
            "01",
            "1.",
            ".5",
            "-",
            "1e",
            "+1",
            "NaN",
            "[1] 2",
            "{'a': 1}",
            "\"\\x\"",
            "\"\u{1}\"",
            "\"\\ud800\"",
            "\"\\udc00\"",
            "tru",
            "[1 2]",
            "{\"a\" 1}",
            "{1: 2}",
            "/* */ 1",
        ] {
            assert!(p(bad).is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn duplicate_keys_are_rejected_with_their_path() {
        let e = p(r#"{"a": {"arc": {"radius": 1, "center": [0, 0], "radius": 2}}}"#).unwrap_err();
        assert_eq!(e.path, "a.arc.radius");
        assert!(e.reason.contains("duplicate"), "{e}");
        let e = p(r#"[{"x": 1}, {"y": [0, {"z": 1, "z": 1}]}]"#).unwrap_err();
        assert_eq!(e.path, "[1].y[1].z");
        assert_eq!((e.line, e.column), (1, 31));
        assert_eq!(e.kind, ErrorKind::Duplicate);
    }

    #[test]
    fn limits_are_checked_while_parsing() {
        let lim = Limits {
            max_bytes: 100,
            max_depth: 3,
            max_nodes: 5,
            max_string_bytes: 4,
            max_number_bytes: 3,
        };
        assert!(parse(&" ".repeat(101), &lim)
            .unwrap_err()
            .reason
            .contains("bytes"));
        assert!(parse("[[[1]]]", &lim).is_ok());
        assert!(parse("[[[[1]]]]", &lim)
            .unwrap_err()
            .reason
            .contains("nested"));
        assert!(parse("[1,2,3,4]", &lim).is_ok());
        let e = parse("[1,2,3,4,5]", &lim).unwrap_err();
        assert!(e.reason.contains("values") && e.path == "[4]", "{e}");
        assert!(parse("\"abcd\"", &lim).is_ok());
        assert!(parse("\"abcde\"", &lim)
            .unwrap_err()
            .reason
            .contains("string"));
        assert!(parse("123", &lim).is_ok());
        assert!(parse("1234", &lim).unwrap_err().reason.contains("number"));
        // a deep document fails at the limit, not with a stack overflow
        let deep = "[".repeat(100_000);
        assert!(p(&deep).unwrap_err().reason.contains("nested"));
    }

    #[test]
    fn escaped_keys_are_compared_decoded() {
        let v = p(r#"{"\u0066ormat": 1, "b\\c": 2}"#).unwrap();
        assert_eq!(v.get("format"), Some(&Json::Number("1")));
        assert_eq!(v.get("b\\c"), Some(&Json::Number("2")));
        assert_eq!(v.get("\\u0066ormat"), None);
        assert_eq!(v.to_value(), serde_json::json!({"format": 1, "b\\c": 2}));
        // a key written twice, once escaped, is a duplicate (small and large objects)
        let e = p(r#"{"a": 1, "\u0061": 2}"#).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Duplicate);
        let members: Vec<String> = (0..20).map(|i| format!("\"k{i}\": {i}")).collect();
        let e = p(&format!("{{{}, \"k\\u0033\": 0}}", members.join(","))).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Duplicate);
        assert!(e.reason.contains("\"k3\""), "{e}");
    }

    #[test]
    fn nodes_are_small() {
        // the sizes the module's documentation states (the memory of a
        // certificate's tree is about these times its values and members)
        assert_eq!(std::mem::size_of::<Json>(), 24);
        assert_eq!(std::mem::size_of::<(Key, Json)>(), 40);
    }

    #[test]
    fn large_objects_check_duplicates_too() {
        let members: Vec<String> = (0..40).map(|i| format!("\"k{i}\": {i}")).collect();
        let doc = format!("{{{}}}", members.join(","));
        assert_eq!(p(&doc).unwrap().as_object().unwrap().len(), 40);
        let doc = format!("{{{}, \"k3\": 0}}", members.join(","));
        assert_eq!(p(&doc).unwrap_err().path, "k3");
    }

    #[test]
    fn exact_numbers_and_duplicate_keys() {
        let doc = parse(r#"{"tol": "1/1000", "n": [1, 2.50]}"#, &Limits::DEFAULT).unwrap();
        assert_eq!(doc.get("tol").and_then(Json::as_str), Some("1/1000"));
        let e = parse(r#"{"tol": "1", "tol": "2"}"#, &Limits::DEFAULT).unwrap_err();
        assert_eq!(e.path, "tol");
        assert!(e.reason.contains("duplicate"));
    }
}
