//! Equations written in plain Unicode (`θ̈ = [g/r − A(cos θ − k2) θ̇²] sin θ`)
//! as MathML: symbols in italic, digits after a symbol as subscripts, dots
//! over symbols as accents, ² and ³ as superscripts, functions upright. An
//! equation is cut into pieces at its top-level `=`, `+` and `−`, each its
//! own `<math>`, so that a long one wraps on a narrow screen (a long piece is
//! cut inside its brackets too, at `+`, `−` and `/`).

use super::page::esc;

const FUNCTIONS: [&str; 10] = [
    "sin", "cos", "tan", "arccos", "arcsin", "arctan", "exp", "ln", "log", "sqrt",
];

/// Whether a code span is prose with symbols in it (a sentence the paper
/// prints, rendered as text): symbols beyond ASCII and three words or more
/// of three letters or more, not counting functions (a command is ASCII).
pub fn is_prose(s: &str) -> bool {
    !s.is_ascii()
        && s.split(|c: char| !c.is_ascii_alphabetic())
            .filter(|w| w.len() >= 3 && !FUNCTIONS.contains(w))
            .count()
            >= 3
}

/// Whether a code span is an equation (rendered as math) rather than a
/// command, a file name or prose.
pub fn is_equation(s: &str) -> bool {
    let t = s.trim();
    !is_prose(t)
        && !t.starts_with("cylroll")
        && !t.contains("--")
        && !t.contains(".toml")
        && !t.contains(".md")
        && (t.contains('=') || t.chars().any(|c| "θφψμ∂θ̇".contains(c)))
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    /// A symbol or word (letters).
    Id(String),
    /// A number.
    Num(String),
    /// An operator or bracket.
    Op(char),
    /// A combining accent on the previous symbol.
    Accent(char),
    /// A superscript digit.
    Sup(char),
    /// A space.
    Space,
    /// `_`: the next token is a subscript.
    Under,
}

fn tokens(s: &str) -> Vec<Tok> {
    let mut out = Vec::new();
    let cs: Vec<char> = s.chars().collect();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c.is_alphabetic() {
            let mut w = String::new();
            // a Greek letter is a symbol of its own; ASCII letters make words
            if c.is_ascii() {
                while i < cs.len() && cs[i].is_ascii_alphabetic() {
                    w.push(cs[i]);
                    i += 1;
                }
            } else {
                w.push(c);
                i += 1;
            }
            out.push(Tok::Id(w));
        } else if c.is_ascii_digit()
            || (c == '.' && cs.get(i + 1).is_some_and(|d| d.is_ascii_digit()))
        {
            let mut w = String::new();
            while i < cs.len() && (cs[i].is_ascii_digit() || cs[i] == '.') {
                w.push(cs[i]);
                i += 1;
            }
            out.push(Tok::Num(w));
        } else {
            out.push(match c {
                '\u{0307}' | '\u{0308}' => Tok::Accent(c),
                '²' | '³' => Tok::Sup(c),
                ' ' => Tok::Space,
                '_' => Tok::Under,
                _ => Tok::Op(c),
            });
            i += 1;
        }
    }
    out
}

fn mi(s: &str) -> String {
    if FUNCTIONS.contains(&s) {
        format!("<mi>{s}</mi>")
    } else if s.chars().count() > 2 {
        format!("<mtext>{}</mtext>", esc(s))
    } else {
        format!("<mi>{}</mi>", esc(s))
    }
}

/// The MathML elements of one piece of an equation.
fn elements(toks: &[Tok]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut sub_next = false;
    let mut i = 0;
    while i < toks.len() {
        let t = &toks[i];
        let el = match t {
            Tok::Id(w) => {
                let mut base = mi(w);
                // accents on a symbol
                while let Some(Tok::Accent(a)) = toks.get(i + 1) {
                    let mark = if *a == '\u{0307}' { "˙" } else { "¨" };
                    base = format!("<mover accent=\"true\">{base}<mo>{mark}</mo></mover>");
                    i += 1;
                }
                // digits or a lone s directly after a symbol: a subscript
                match toks.get(i + 1) {
                    Some(Tok::Num(n)) if !n.contains('.') && w.chars().count() <= 2 => {
                        i += 1;
                        format!("<msub>{base}<mn>{n}</mn></msub>")
                    }
                    Some(Tok::Id(s)) if s == "s" && !w.is_ascii() => {
                        i += 1;
                        format!("<msub>{base}<mi>s</mi></msub>")
                    }
                    _ => base,
                }
            }
            Tok::Num(n) => format!("<mn>{n}</mn>"),
            Tok::Op(c) => format!("<mo>{}</mo>", esc(&c.to_string())),
            Tok::Accent(_) => String::new(),
            Tok::Sup(c) => {
                let base = out.pop().unwrap_or_default();
                let d = if *c == '²' { "2" } else { "3" };
                format!("<msup>{base}<mn>{d}</mn></msup>")
            }
            Tok::Space => String::new(),
            Tok::Under => {
                sub_next = true;
                String::new()
            }
        };
        if el.is_empty() {
            i += 1;
            continue;
        }
        if sub_next && !matches!(t, Tok::Under) {
            let base = out.pop().unwrap_or_default();
            out.push(format!("<msub>{base}<mrow>{el}</mrow></msub>"));
            sub_next = false;
        } else {
            // a space between two words of text
            if matches!(t, Tok::Id(w) if w.chars().count() > 2 && !FUNCTIONS.contains(&w.as_str()))
                && out.last().is_some_and(|l| l.starts_with("<mtext>"))
            {
                out.push("<mspace width=\"0.3em\"/>".into());
            }
            out.push(el);
        }
        i += 1;
    }
    out.concat()
}

/// An equation as MathML pieces, cut at top-level `=`, `+`, `−` so that it
/// wraps; the plain text kept as the pieces' `alttext`.
pub fn mathml(eq: &str) -> String {
    let toks = tokens(eq);
    let mut pieces: Vec<Vec<Tok>> = vec![Vec::new()];
    let mut depth = 0i32;
    // a piece this long is cut inside brackets too (at `+`, `−`) and at `/`
    const LONG: usize = 8;
    for (k, t) in toks.iter().enumerate() {
        if let Tok::Op(c) = t {
            let long = pieces
                .last()
                .is_some_and(|p| p.iter().filter(|t| **t != Tok::Space).count() >= LONG);
            match c {
                '(' | '[' | '{' => depth += 1,
                ')' | ']' | '}' => depth -= 1,
                '=' | '+' | '−' if k > 0 && (depth == 0 || long) => {
                    pieces.push(Vec::new());
                }
                '/' if k > 0 && long => pieces.push(Vec::new()),
                _ => {}
            }
        }
        if let Some(p) = pieces.last_mut() {
            p.push(t.clone());
        }
    }
    let parts: Vec<String> = pieces
        .iter()
        .filter(|p| p.iter().any(|t| *t != Tok::Space))
        .map(|p| format!("<math>{}</math>", elements(p)))
        .collect();
    format!(
        "<span class=\"eq\" title=\"{}\">{}</span>",
        esc(eq),
        parts.join(" ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equations_become_mathml() {
        let m = mathml("r θ̇s² = g cos θs + r1 sin θs φ̈1");
        assert!(
            m.contains("<mover accent=\"true\"><mi>θ</mi><mo>˙</mo></mover>"),
            "{m}"
        );
        assert!(m.contains("<mi>cos</mi>"));
        assert!(m.contains("<msub><mi>r</mi><mn>1</mn></msub>"), "{m}");
        assert!(m.matches("<math>").count() >= 3, "cut at = and +: {m}");
        assert!(is_equation("N12 = m2 (g cos θ)"));
        // a long bracket is cut too, so that no piece is wider than a phone
        let long = mathml("θ̈ = [g/r − A(cos θ − k2) θ̇²] sin θ / [1 + k2 − A(cos θ − k2)²]");
        assert!(long.matches("<math>").count() >= 4, "{long}");
        assert!(!is_equation("cylroll audit --equation 21"));
        assert!(!is_equation("the only steady motion is θ ≡ 0, φ1 = ω0 t"));
        assert!(is_prose("the only steady motion is θ ≡ 0, φ1 = ω0 t"));
        assert!(!is_prose("cylroll separation --branch part"));
        assert!(is_equation("p_φ1 = (k1 m1 + k2 m2) r1² φ̇1 − k2 m2 r1 r θ̇"));
    }
}
