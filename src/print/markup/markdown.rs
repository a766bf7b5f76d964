//! A title in Markdown: its words with Markdown's marks escaped (`\ ` * _ [ ] < > # | ~ $`),
//! so that `I_xy` or `[I]` never turns into emphasis or a link, and its mathematics as
//! `$…$` in the LaTeX of [`super::latex`].

/// Words in Markdown.
pub fn words(out: &mut String, words: &str) {
    for c in words.chars() {
        if "\\`*_[]<>#|~$".contains(c) {
            out.push('\\');
        }
        out.push(c);
    }
}
