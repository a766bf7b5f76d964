//! A title in Markdown: its words with Markdown's marks escaped (`\ ` * _ [ ] # | ~ $` by a
//! backslash; `< > &` as HTML's references, so that no tag or reference is ever formed and
//! `<script>` reaches no renderer as a tag), so that `I_xy` or `[I]` never turns into
//! emphasis or a link, a character a reader cannot see as its escape `\u{1b}`; and its
//! mathematics as `$…$` in the LaTeX of [`super::latex`], where `<`, `>`, `&`, `[` and `]`
//! are the commands `\lt`, `\gt`, `\And`, `\lbrack` and `\rbrack` (MathJax's and KaTeX's),
//! never the characters.

use crate::visible;

/// Words in Markdown.
pub fn words(out: &mut String, words: &str) {
    for c in words.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            c if "\\`*_[]#|~$".contains(c) => {
                out.push('\\');
                out.push(c);
            }
            c if visible::is_hidden(c) => {
                out.push('\\');
                visible::push_escape(out, c);
            }
            c => out.push(c),
        }
    }
}
