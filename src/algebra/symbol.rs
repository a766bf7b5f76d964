//! Interned symbols: each knows its ASCII name, its LaTeX form, its order of time
//! derivative and its role in a formula.
//!
//! Names follow one convention, read by [`Symbol::new`]:
//!
//! ```text
//! name      = base ["bar"] ["dot" | "ddot"] [digits] ["_" subscript]
//! w_x       -> \omega_x          (ω, time-dependent)
//! wdot_x    -> \dot{\omega}_x    (ω̇: the time derivative of w_x)
//! w1        -> \omega_1          (trailing digits are a subscript: the same symbol as w_1)
//! I_xy      -> I_{xy}            (a product of inertia)
//! vbar_x    -> \bar{v}_x
//! Dt        -> \Delta t
//! SumM_x    -> \Sigma M_x        (a resultant)
//! m_body    -> m_{\text{body}}   (a word as subscript is upright; axes stay italic)
//! Lb        -> \mathit{Lb}       (a name of several letters, never read as L times b)
//! I'        -> I'                (primes after a name without subscript: I′, a moment)
//! ```
//!
//! `w` (ω) and `Dt` (Δt) are the chapter's aliases; [`Symbol::plain_latex`] is the spelling
//! without them (`w`, `\mathit{Dt}`), which a page that also holds `omega` prints `w` in.
//!
//! The role decides the order of factors in a printed product (numbers, then inertia and
//! mass, then other quantities, then lengths, then kinematic symbols) and which symbols
//! depend on time: only kinematic ones (`w`, `omega`, `Omega`, `alpha`, `theta`, `phi`,
//! `psi`, `v`, `vbar`, axis components `a_x`, ... and every dotted symbol).
//!
//! ```
//! use kinetics::algebra::Symbol;
//! let w = Symbol::new("w_x");
//! assert_eq!(w.latex(), r"\omega_x");
//! assert_eq!(w.dot().latex(), r"\dot{\omega}_x");
//! assert_eq!(w.dot().name(), "wdot_x");
//! assert_eq!(Symbol::new("w1"), Symbol::new("w_1"));
//! ```

use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::fmt;
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::sync::{Mutex, OnceLock};

/// What a symbol stands for; decides factor order in print and time dependence.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Role {
    /// Moments and products of inertia: `I_x`, `I_xy`, `I`.
    Inertia,
    /// Mass: `m`, `m_1`.
    Mass,
    /// Forces, couples, impulses, times, constant angles, everything not classified.
    Other,
    /// Lengths: `L`, `l`, `r`, `a`, `b`, `c`, `d`, `h`, `x`, `y`, `z`, `xbar`, ...
    Length,
    /// Time-dependent quantities: angular velocities and accelerations, velocities,
    /// accelerations, Euler angles, and any derivative.
    Kinematic,
    /// The unit vectors `i`, `j`, `k` of a vector sum.
    UnitVector,
}

/// The data behind a [`Symbol`], interned once per distinct name for the process's life.
#[derive(Debug)]
pub struct SymbolData {
    name: Box<str>,
    /// The first eight bytes of `name`, big-endian and zero-padded: comparing these orders
    /// most pairs of names without reading the strings.
    name_prefix: u64,
    base: Box<str>,
    barred: bool,
    dots: u8,
    subscript: Box<str>,
    /// The axis the subscript names (see [`axis_of_subscript`]).
    axis: Option<usize>,
    role: Role,
    latex: Box<str>,
    /// The LaTeX without the aliases `w` → ω and `Dt` → Δt.
    plain_latex: Box<str>,
}

/// An interned symbol; copying and comparing for equality are pointer operations.
#[derive(Clone, Copy)]
pub struct Symbol(&'static SymbolData);

const GREEK: [&str; 30] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Sigma", "Phi", "Omega",
];

fn interner() -> &'static Mutex<HashMap<Box<str>, &'static SymbolData>> {
    static INTERNER: OnceLock<Mutex<HashMap<Box<str>, &'static SymbolData>>> = OnceLock::new();
    INTERNER.get_or_init(|| Mutex::new(HashMap::new()))
}

thread_local! {
    /// This thread's copy of the names it has looked up, in front of the shared interner,
    /// so that a repeated `Symbol::new` takes no lock.
    static LOOKED_UP: RefCell<HashMap<Box<str>, Symbol, BuildHasherDefault<NameHasher>>> =
        RefCell::new(HashMap::default());
}

/// FNV-1a, a hash that is quick on the few bytes of a symbol name (the names a thread
/// looks up are its own, so resistance to chosen collisions is not needed here).
struct NameHasher(u64);

impl Default for NameHasher {
    fn default() -> NameHasher {
        NameHasher(0xcbf2_9ce4_8422_2325)
    }
}

impl Hasher for NameHasher {
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// How many symbols [`RECENT`] holds (a power of two).
const RECENT_SLOTS: usize = 128;

thread_local! {
    /// Symbols this thread looked up by their canonical names, at most one in each slot,
    /// the slot chosen by the name's hash: in front of [`LOOKED_UP`], a hit costs a hash
    /// and one comparison of the name.
    static RECENT: [Cell<Option<Symbol>>; RECENT_SLOTS] =
        const { [const { Cell::new(None) }; RECENT_SLOTS] };
}

impl Symbol {
    /// The symbol with this ASCII name (see the module documentation for the convention).
    /// The caller guarantees the name is well formed: an ASCII letter followed by letters,
    /// digits, `_` and `'` (the parser checks this for user input).
    pub fn new(name: &str) -> Symbol {
        let mut hasher = NameHasher::default();
        hasher.write(name.as_bytes());
        // Fibonacci hashing: the multiplication carries every bit of the hash into the top
        // bits, which pick the slot (FNV's own top bits hardly depend on the last bytes).
        let mixed = hasher.finish().wrapping_mul(0x9e37_79b9_7f4a_7c15);
        let slot = (mixed >> (64 - RECENT_SLOTS.trailing_zeros())) as usize;
        RECENT.with(|recent| match recent[slot].get() {
            Some(symbol) if symbol.name() == name => symbol,
            _ => {
                let symbol = Symbol::looked_up(name);
                if symbol.name() == name {
                    recent[slot].set(Some(symbol));
                }
                symbol
            }
        })
    }

    /// The symbol with this name from this thread's names looked up, else from the shared
    /// interner.
    fn looked_up(name: &str) -> Symbol {
        LOOKED_UP.with(|cache| {
            if let Some(&symbol) = cache.borrow().get(name) {
                return symbol;
            }
            let symbol = Symbol::intern(name);
            cache.borrow_mut().insert(name.into(), symbol);
            symbol
        })
    }

    /// The symbol with this name from the process-wide interner, created on first use.
    fn intern(name: &str) -> Symbol {
        let mut map = interner()
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some(data) = map.get(name) {
            return Symbol(data);
        }
        let data = SymbolData::from_name(name);
        let data: &'static SymbolData = match map.get(&*data.name) {
            Some(existing) => existing,
            None => {
                let leaked: &'static SymbolData = Box::leak(Box::new(data));
                map.insert(leaked.name.clone(), leaked);
                leaked
            }
        };
        map.insert(name.into(), data);
        Symbol(data)
    }

    /// The canonical ASCII name: `wdot_x`, `I_xy`, `w_1`.
    pub fn name(self) -> &'static str {
        &self.0.name
    }

    /// The LaTeX form: `\dot{\omega}_x`, `I_{xy}`.
    pub fn latex(self) -> &'static str {
        &self.0.latex
    }

    /// The LaTeX form without the chapter's aliases: `w_x` (not `\omega_x`), `\mathit{Dt}`
    /// (not `\Delta t`); the same as [`Symbol::latex`] for every other name. A page that holds
    /// both `w_x` and `omega_x` prints the first so (`print::on_one_page`).
    pub fn plain_latex(self) -> &'static str {
        &self.0.plain_latex
    }

    pub fn role(self) -> Role {
        self.0.role
    }

    /// The subscript as written (`x`, `xy`, `1`, `x'`), empty when there is none.
    pub fn subscript(self) -> &'static str {
        &self.0.subscript
    }

    /// The axis its subscript names: 0 for `w_x` and `w_x'`, none for `I_xy` or `m`.
    pub fn axis(self) -> Option<usize> {
        self.0.axis
    }

    /// The base name without decoration or subscript: `w` for `wdot_x`.
    pub fn base(self) -> &'static str {
        &self.0.base
    }

    /// How many times this symbol has been differentiated with respect to time.
    pub fn dots(self) -> u8 {
        self.0.dots
    }

    /// Whether `d/dt` of this symbol is non-zero.
    pub fn is_time_dependent(self) -> bool {
        self.0.role == Role::Kinematic
    }

    /// The time derivative `ẋ` of this symbol.
    pub fn dot(self) -> Symbol {
        let d = self.0;
        Symbol::new(&compose_name(&d.base, d.barred, d.dots + 1, &d.subscript))
    }

    /// True for the derivative of a kinematic symbol (an acceleration-like quantity) and
    /// for symbols that name an acceleration (`alpha`, `a_x`). An angle's first rate is a
    /// velocity (`phidot`, φ̇, the rate of precession), its second an acceleration (`phiddot`).
    pub fn is_acceleration(self) -> bool {
        let angle = matches!(&*self.0.base, "theta" | "phi" | "psi");
        self.0.dots > u8::from(angle)
            || &*self.0.base == "alpha"
            || (&*self.0.base == "a" && self.0.role == Role::Kinematic)
    }
}

fn compose_name(base: &str, barred: bool, dots: u8, subscript: &str) -> String {
    let mut name = base.to_string();
    if barred {
        name.push_str("bar");
    }
    match dots {
        0 => {}
        1 => name.push_str("dot"),
        2 => name.push_str("ddot"),
        n => name.push_str(&format!("d{n}ot")),
    }
    if !subscript.is_empty() {
        name.push('_');
        name.push_str(subscript);
    }
    name
}

impl SymbolData {
    fn from_name(name: &str) -> SymbolData {
        let (head, mut subscript) = match name.split_once('_') {
            Some((h, s)) => (h, s.to_string()),
            None => (name, String::new()),
        };
        let mut head = head;
        // A primed name without a subscript (`I'`, the transverse moment of an
        // axisymmetric body) keeps its primes on the base and takes no digits, dots or bar.
        let primed = subscript.is_empty() && head.ends_with('\'');
        if subscript.is_empty() && !primed {
            let digits = head.len() - head.trim_end_matches(|c: char| c.is_ascii_digit()).len();
            if digits > 0 && digits < head.len() {
                subscript = head[head.len() - digits..].to_string();
                head = &head[..head.len() - digits];
            }
        }
        let mut dots = 0u8;
        for (suffix, n) in [("ddot", 2u8), ("dot", 1u8)] {
            if !primed && head.len() > suffix.len() && head.ends_with(suffix) {
                head = &head[..head.len() - suffix.len()];
                dots = n;
                break;
            }
        }
        let mut barred = false;
        if !primed && head.len() > 3 && head.ends_with("bar") {
            head = &head[..head.len() - 3];
            barred = true;
        }
        let role = classify(head, barred, dots, &subscript);
        let latex = latex_of(head, barred, dots, &subscript, true);
        let plain_latex = latex_of(head, barred, dots, &subscript, false);
        let name = compose_name(head, barred, dots, &subscript);
        SymbolData {
            name_prefix: name_prefix(&name),
            name: name.into(),
            base: head.into(),
            barred,
            dots,
            axis: axis_of_subscript(&subscript),
            subscript: subscript.into(),
            role,
            latex: latex.into(),
            plain_latex: plain_latex.into(),
        }
    }
}

/// The first eight bytes of a name as a big-endian integer, zero-padded: for names without
/// NUL bytes, `name_prefix(a) < name_prefix(b)` implies `a < b`, and equal prefixes of
/// distinct names leave the order to the full strings.
fn name_prefix(name: &str) -> u64 {
    let mut bytes = [0u8; 8];
    let n = name.len().min(8);
    bytes[..n].copy_from_slice(&name.as_bytes()[..n]);
    u64::from_be_bytes(bytes)
}

/// The axis a subscript names, primes ignored: `x` or `X` is 0, `y` 1, `z` 2, anything
/// else (`xy`, `1`, empty) none.
pub fn axis_of_subscript(subscript: &str) -> Option<usize> {
    match subscript.trim_end_matches('\'') {
        "x" | "X" => Some(0),
        "y" | "Y" => Some(1),
        "z" | "Z" => Some(2),
        _ => None,
    }
}

fn is_axis_subscript(subscript: &str) -> bool {
    !subscript.is_empty()
        && subscript
            .chars()
            .all(|c| matches!(c, 'x' | 'y' | 'z' | 'X' | 'Y' | 'Z' | '\''))
}

fn classify(base: &str, barred: bool, dots: u8, subscript: &str) -> Role {
    let base = base.trim_end_matches('\'');
    if dots > 0 {
        return Role::Kinematic;
    }
    match base {
        "i" | "j" | "k" if subscript.is_empty() && !barred => Role::UnitVector,
        "I" => Role::Inertia,
        "m" => Role::Mass,
        "w" | "omega" | "Omega" | "alpha" | "theta" | "phi" | "psi" | "v" => Role::Kinematic,
        "a" if barred || is_axis_subscript(subscript) => Role::Kinematic,
        "L" | "l" | "r" | "a" | "b" | "c" | "d" | "h" | "x" | "y" | "z" | "e" => Role::Length,
        _ => Role::Other,
    }
}

/// The LaTeX of a name's parts; `aliases` spells `w` as ω and `Dt` as Δt. A base of several
/// letters that is not Greek is `\mathit{Lb}` (one name, not the product `L b`); a subscript
/// that is a word (two or more letters, one of them lower case and not an axis) is upright,
/// `m_{\text{body}}`, while `I_{xy}`, `C_{AB}` and `\omega_{12}` stay italic.
fn latex_of(base: &str, barred: bool, dots: u8, subscript: &str, aliases: bool) -> String {
    let stem = base.trim_end_matches('\'');
    if stem.len() < base.len() {
        // `I'` is I′: the letter's spelling, then its primes.
        let primes = &base[stem.len()..];
        return format!(
            "{}{primes}",
            latex_of(stem, barred, dots, subscript, aliases)
        );
    }
    if let Some(rest) = base.strip_prefix("Sum").filter(|r| !r.is_empty()) {
        // `SumM_x` is the resultant ΣM_x.
        return format!(
            r"\Sigma {}",
            latex_of(rest, barred, dots, subscript, aliases)
        );
    }
    let mut core = if base == "w" && aliases {
        r"\omega".to_string()
    } else if base == "Dt" && aliases {
        r"\Delta t".to_string()
    } else if GREEK.contains(&base) {
        format!(r"\{base}")
    } else if matches!(base, "i" | "j" | "k") && subscript.is_empty() && !barred && dots == 0 {
        format!(r"\mathbf{{{base}}}")
    } else if base.chars().count() > 1 {
        format!(r"\mathit{{{base}}}")
    } else {
        base.to_string()
    };
    if barred {
        core = format!(r"\bar{{{core}}}");
    }
    core = match dots {
        0 => core,
        1 => format!(r"\dot{{{core}}}"),
        2 => format!(r"\ddot{{{core}}}"),
        n => format!(r"\overset{{({n})}}{{{core}}}"),
    };
    if subscript.is_empty() {
        core
    } else if is_word(subscript) {
        format!(r"{core}_{{\text{{{subscript}}}}}")
    } else if subscript.len() == 1 {
        format!("{core}_{subscript}")
    } else {
        format!("{core}_{{{subscript}}}")
    }
}

/// A subscript that is a word, not axes, points or digits: `body`, `rot`, `frame`.
fn is_word(subscript: &str) -> bool {
    subscript.len() > 1
        && subscript.chars().all(|c| c.is_ascii_alphabetic())
        && subscript
            .chars()
            .any(|c| c.is_ascii_lowercase() && !matches!(c, 'x' | 'y' | 'z'))
}

impl PartialEq for Symbol {
    #[inline]
    fn eq(&self, other: &Symbol) -> bool {
        std::ptr::eq(self.0, other.0)
    }
}

impl Eq for Symbol {}

impl Hash for Symbol {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.name.hash(state)
    }
}

impl Ord for Symbol {
    #[inline]
    fn cmp(&self, other: &Symbol) -> std::cmp::Ordering {
        if self == other {
            std::cmp::Ordering::Equal
        } else {
            self.0
                .name_prefix
                .cmp(&other.0.name_prefix)
                .then_with(|| self.0.name.cmp(&other.0.name))
        }
    }
}

impl PartialOrd for Symbol {
    fn partial_cmp(&self, other: &Symbol) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Debug for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// More names than the recent-symbol slots, so that names share slots and evict each
    /// other: every lookup, hit or miss, alias or canonical name, gives the right symbol.
    #[test]
    fn recent_symbols_agree_with_the_interner() {
        let names: Vec<String> = (0..3 * RECENT_SLOTS).map(|i| format!("q{i}")).collect();
        for round in 0..3 {
            for name in names.iter().rev().skip(round) {
                let symbol = Symbol::new(name);
                assert_eq!(symbol.base(), "q");
                assert_eq!(symbol.subscript(), &name[1..]);
                assert_eq!(symbol, Symbol::new(&format!("q_{}", &name[1..])));
                assert_eq!(symbol, Symbol::new(name));
            }
        }
    }

    #[test]
    fn names_latex_and_roles() {
        let cases = [
            ("I_xy", "I_{xy}", Role::Inertia),
            ("w_x", r"\omega_x", Role::Kinematic),
            ("wdot_x", r"\dot{\omega}_x", Role::Kinematic),
            ("alpha", r"\alpha", Role::Kinematic),
            ("beta", r"\beta", Role::Other),
            ("Dt", r"\Delta t", Role::Other),
            ("a", "a", Role::Length),
            ("a_x", "a_x", Role::Kinematic),
            ("vbar_x", r"\bar{v}_x", Role::Kinematic),
            ("I_x'", "I_{x'}", Role::Inertia),
            ("i", r"\mathbf{i}", Role::UnitVector),
            ("m", "m", Role::Mass),
            ("thetaddot", r"\ddot{\theta}", Role::Kinematic),
            ("SumM_x", r"\Sigma M_x", Role::Other),
            ("m_body", r"m_{\text{body}}", Role::Mass),
            ("T_rot", r"T_{\text{rot}}", Role::Other),
            ("C_AB", "C_{AB}", Role::Other),
            ("I_xy'", "I_{xy'}", Role::Inertia),
            ("Lb", r"\mathit{Lb}", Role::Other),
            ("SumLb", r"\Sigma \mathit{Lb}", Role::Other),
            ("I'", "I'", Role::Inertia),
            ("I''", "I''", Role::Inertia),
        ];
        for (name, latex, role) in cases {
            let s = Symbol::new(name);
            assert_eq!(s.latex(), latex, "{name}");
            assert_eq!(s.role(), role, "{name}");
        }
    }

    #[test]
    fn the_plain_spelling_drops_only_the_aliases() {
        for (name, plain) in [
            ("w_x", "w_x"),
            ("wdot_1", r"\dot{w}_1"),
            ("Dt", r"\mathit{Dt}"),
            ("omega_x", r"\omega_x"),
            ("I_xy", "I_{xy}"),
        ] {
            assert_eq!(Symbol::new(name).plain_latex(), plain, "{name}");
        }
        assert_eq!(Symbol::new("w_x").latex(), Symbol::new("omega_x").latex());
    }

    #[test]
    fn derivative_names_round_trip() {
        let w = Symbol::new("w1");
        assert_eq!(w.name(), "w_1");
        assert_eq!(w.dot(), Symbol::new("wdot_1"));
        assert_eq!(w.dot().dot(), Symbol::new("wddot1"));
        assert!(!Symbol::new("L").is_time_dependent());
    }

    #[test]
    fn order_is_the_order_of_names() {
        let names = [
            "I",
            "I_x",
            "I_xy",
            "I_xz",
            "I_y",
            "alpha",
            "alphadot",
            "w",
            "w_x",
            "w_y",
            "wdot_x",
            "wdot_xy",
            "wdot_xz",
            "thetaddot_x'",
            "a",
        ];
        for a in names {
            for b in names {
                let (sa, sb) = (Symbol::new(a), Symbol::new(b));
                assert_eq!(sa.cmp(&sb), sa.name().cmp(sb.name()), "{a} vs {b}");
            }
        }
    }

    #[test]
    fn other_threads_get_the_same_symbols() {
        let here = Symbol::new("omega_thread");
        let there = std::thread::spawn(|| Symbol::new("omega_thread"))
            .join()
            .expect("thread ran");
        assert_eq!(here, there);
    }
}
