//! The pages marking writes (a student's feedback, the class's summary) as typed blocks, and
//! their two writers, Markdown and HTML: each page is built once and each writer walks it.

use crate::print::markup::markdown_words;
use crate::print::mathml::escaped as html_escaped;

/// A run of text inside a block.
#[derive(Debug, Clone, PartialEq)]
pub enum Inline {
    Text(String),
    /// What a person typed or a formula in the checker's text notation, set as code.
    Code(String),
    Strong(String),
}

/// Words in which a formula is quoted between backticks (a reading's explanation:
/// "the sign of `3*M*L/(16*c)` is flipped") as text and code.
pub fn words_and_code(text: &str) -> Vec<Inline> {
    text.split('`')
        .enumerate()
        .filter(|(_, part)| !part.is_empty())
        .map(|(k, part)| match k % 2 {
            0 => Inline::Text(part.to_string()),
            _ => Inline::Code(part.to_string()),
        })
        .collect()
}

/// A block of a page.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A heading of level 1 to 3.
    Heading(u8, String),
    Paragraph(Vec<Inline>),
    /// Lines set as they are (an answer, a check's report).
    Preformatted(String),
    /// Words of the instructor's, quoted.
    Quote(String),
    Table {
        header: Vec<String>,
        rows: Vec<Vec<Vec<Inline>>>,
    },
}

/// A page: its title and blocks.
#[derive(Debug, Clone, PartialEq)]
pub struct Document {
    pub title: String,
    pub blocks: Vec<Block>,
}

fn inline_markdown(out: &mut String, inlines: &[Inline]) {
    for inline in inlines {
        match inline {
            Inline::Text(t) => out.push_str(&markdown_words(t)),
            Inline::Strong(t) => {
                out.push_str("**");
                out.push_str(&markdown_words(t));
                out.push_str("**");
            }
            Inline::Code(t) => {
                // A fence longer than any run of backticks inside; `|` escaped for tables.
                let longest = t.split(|c| c != '`').map(str::len).max().unwrap_or(0);
                let fence = "`".repeat(longest + 1);
                let code = t.replace('|', "\\|").replace('\n', " ");
                out.push_str(&format!("{fence} {code} {fence}"));
            }
        }
    }
}

/// The page in Markdown (CommonMark with GitHub's tables).
pub fn markdown(doc: &Document) -> String {
    let mut out = format!("# {}\n\n", markdown_words(&doc.title));
    for block in &doc.blocks {
        match block {
            Block::Heading(level, words) => {
                let marks = "#".repeat(usize::from(*level).clamp(1, 3) + 1);
                out.push_str(&format!("{marks} {}\n\n", markdown_words(words)));
            }
            Block::Paragraph(inlines) => {
                inline_markdown(&mut out, inlines);
                out.push_str("\n\n");
            }
            Block::Preformatted(text) => {
                let longest = text.split(|c| c != '`').map(str::len).max().unwrap_or(0);
                let fence = "`".repeat((longest + 1).max(3));
                out.push_str(&format!("{fence}text\n{}\n{fence}\n\n", text.trim_end()));
            }
            Block::Quote(words) => {
                for line in words.lines() {
                    out.push_str(&format!("> {}\n", markdown_words(line)));
                }
                out.push('\n');
            }
            Block::Table { header, rows } => {
                let cells: Vec<String> = header.iter().map(|h| markdown_words(h)).collect();
                out.push_str(&format!("| {} |\n", cells.join(" | ")));
                out.push_str(&format!("|{}\n", " --- |".repeat(header.len())));
                for row in rows {
                    let cells: Vec<String> = row
                        .iter()
                        .map(|cell| {
                            let mut c = String::new();
                            inline_markdown(&mut c, cell);
                            c
                        })
                        .collect();
                    out.push_str(&format!("| {} |\n", cells.join(" | ")));
                }
                out.push('\n');
            }
        }
    }
    out
}

fn inline_html(out: &mut String, inlines: &[Inline]) {
    for inline in inlines {
        match inline {
            Inline::Text(t) => out.push_str(&html_escaped(t)),
            Inline::Strong(t) => out.push_str(&format!("<strong>{}</strong>", html_escaped(t))),
            Inline::Code(t) => out.push_str(&format!("<code>{}</code>", html_escaped(t))),
        }
    }
}

/// The style of the HTML pages: readable on a screen and printed.
const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:52rem;margin:2rem auto;\
padding:0 1rem;line-height:1.45;color:#222}table{border-collapse:collapse;margin:.5rem 0 1rem}\
td,th{border:1px solid #bbb;padding:.25rem .6rem;text-align:left;vertical-align:top}\
th{background:#f0f0f0}pre{background:#f7f7f7;padding:.6rem;white-space:pre-wrap;overflow-wrap:anywhere}\
code{background:#f3f3f3;padding:0 .2rem}blockquote{border-left:4px solid #7a9;margin:0;\
padding:.2rem .8rem;background:#f4faf6}";

/// The page as a standalone HTML document.
pub fn html(doc: &Document) -> String {
    let title = html_escaped(&doc.title);
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{title}</title>\n\
         <style>{STYLE}</style>\n</head>\n<body>\n<h1>{title}</h1>\n"
    );
    for block in &doc.blocks {
        match block {
            Block::Heading(level, words) => {
                let h = usize::from(*level).clamp(1, 3) + 1;
                out.push_str(&format!("<h{h}>{}</h{h}>\n", html_escaped(words)));
            }
            Block::Paragraph(inlines) => {
                out.push_str("<p>");
                inline_html(&mut out, inlines);
                out.push_str("</p>\n");
            }
            Block::Preformatted(text) => {
                out.push_str(&format!("<pre>{}</pre>\n", html_escaped(text.trim_end())));
            }
            Block::Quote(words) => {
                out.push_str(&format!(
                    "<blockquote>{}</blockquote>\n",
                    html_escaped(words)
                ));
            }
            Block::Table { header, rows } => {
                out.push_str("<table>\n<tr>");
                for h in header {
                    out.push_str(&format!("<th>{}</th>", html_escaped(h)));
                }
                out.push_str("</tr>\n");
                for row in rows {
                    out.push_str("<tr>");
                    for cell in row {
                        out.push_str("<td>");
                        inline_html(&mut out, cell);
                        out.push_str("</td>");
                    }
                    out.push_str("</tr>\n");
                }
                out.push_str("</table>\n");
            }
        }
    }
    out.push_str("</body>\n</html>\n");
    out
}
