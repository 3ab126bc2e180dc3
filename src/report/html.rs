//! index.html from report.md: a small renderer for the markdown subset the
//! report and the analyses' sections use (headings, paragraphs, pipe tables,
//! lists, fenced code, images, `code`, **bold**, *italic*, links). Images of
//! SVG files in the out dir are inlined, so the page opens offline with no
//! external fetches of any kind.

use super::contents::{Anchors, heading};
use std::path::Path;

/// A table longer than this many rows is folded, with a filter for its rows.
const LONG: usize = 30;

const STYLE: &str = "body{font-family:system-ui,sans-serif;max-width:72rem;margin:2rem auto;\
padding:0 1rem;color:#222;line-height:1.45;overflow-wrap:break-word}\
.scroll{overflow-x:auto}table{border-collapse:collapse;margin:1rem 0;font-size:.9rem}\
th,td{border:1px solid #ccc;padding:.25rem .5rem}th{background:#f2f2f2}\
tr:nth-child(even) td{background:#fafafa}td.num,th.num{text-align:right}\
code{background:#f4f4f4;padding:0 .2rem;border-radius:3px}\
pre{background:#f4f4f4;padding:.6rem;overflow-x:auto}\
blockquote{margin:1rem 0;padding:0 1rem;border-left:4px solid #ccc;color:#444}\
figure{margin:1.2rem 0}figure svg{max-width:100%;height:auto}\
figcaption{color:#555;font-size:.9rem}\
.player{display:flex;gap:.6rem;align-items:center;max-width:720px}.player input{flex:1}h1,h2{border-bottom:1px solid #ddd}\
.findings{border:2px solid #5a8f6a;border-radius:6px;background:#f5faf6;padding:0 1rem;margin:1rem 0}\
.findings h2{border:none}summary{cursor:pointer}summary>h2,summary>h3{display:inline}\
details.long>summary{color:#2a5d8f}input.filter{display:block;margin:.5rem 0;width:20rem;max-width:100%}";

/// A row filter for each folded long table, on pages that have one.
const FILTER: &str = "<script>\n\
document.querySelectorAll('input.filter').forEach(input => {\n\
  const rows = [...input.parentElement.querySelectorAll('tbody tr')];\n\
  input.oninput = () => {\n\
    const q = input.value.toLowerCase();\n\
    rows.forEach(r => { r.hidden = q !== '' && !r.textContent.toLowerCase().includes(q); });\n\
  };\n\
});\n\
</script>\n";

/// Under each movie (an animated SVG of class `movie`): a pause button, a
/// time slider and the simulated time. Only pages with a movie carry it.
const PLAYER: &str = "<script>\n\
document.querySelectorAll('svg.movie').forEach(svg => {\n\
  const T = +svg.dataset.duration, P = +svg.dataset.playback;\n\
  const bar = document.createElement('div');\n\
  const play = document.createElement('button');\n\
  const slider = document.createElement('input');\n\
  const label = document.createElement('span');\n\
  bar.className = 'player';\n\
  play.textContent = 'Pause';\n\
  Object.assign(slider, {type: 'range', min: 0, max: P, step: 'any', value: 0});\n\
  slider.setAttribute('aria-label', 'time');\n\
  bar.append(play, slider, label);\n\
  svg.after(bar);\n\
  const show = () => {\n\
    const t = svg.getCurrentTime() % P;\n\
    slider.value = t;\n\
    label.textContent = 't = ' + (t / P * T).toFixed(2);\n\
  };\n\
  const pause = () => { svg.pauseAnimations(); play.textContent = 'Play'; };\n\
  play.onclick = () => {\n\
    if (!svg.animationsPaused()) return pause();\n\
    svg.unpauseAnimations();\n\
    play.textContent = 'Pause';\n\
  };\n\
  slider.oninput = () => { pause(); svg.setCurrentTime(+slider.value); show(); };\n\
  const tick = () => { if (!svg.animationsPaused()) show(); requestAnimationFrame(tick); };\n\
  tick();\n\
});\n\
</script>\n";

/// The whole page for `markdown`; figures are read from `out_dir`.
pub fn page(title: &str, markdown: &str, out_dir: &Path) -> String {
    let body = body(markdown, out_dir);
    let used = |script, mark| if body.contains(mark) { script } else { "" };
    let player =
        used(PLAYER, "<svg class=\"movie\"").to_string() + used(FILTER, "class=\"filter\"");
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{body}{player}</body>\n</html>\n",
        escape(title),
    )
}

/// Block-level rendering, line by line.
pub fn body(markdown: &str, out_dir: &Path) -> String {
    blocks(markdown, out_dir, &mut Anchors::default())
}

/// `body`, its headings given the next of `anchors`.
fn blocks(markdown: &str, out_dir: &Path, anchors: &mut Anchors) -> String {
    let lines: Vec<&str> = markdown.lines().collect();
    let mut html = String::new();
    let mut para: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let t = line.trim();
        let block = t.is_empty()
            || t.starts_with("```")
            || heading(t).is_some()
            || t.starts_with('|')
            || quoted(t).is_some()
            || list_item(t).is_some()
            || image(t).is_some();
        if block {
            flush(&mut html, &mut para);
        }
        if t.is_empty() {
            i += 1;
        } else if t.starts_with("```") {
            let end = (i + 1..lines.len())
                .find(|&j| lines[j].trim().starts_with("```"))
                .unwrap_or(lines.len());
            html.push_str("<pre><code>");
            for l in &lines[i + 1..end] {
                html.push_str(&escape(l));
                html.push('\n');
            }
            html.push_str("</code></pre>\n");
            i = end + 1;
        } else if let Some((level, text)) = heading(t) {
            let id = escape(&anchors.next(text));
            let h = format!("<h{level} id=\"{id}\">{}</h{level}>\n", inline(text));
            // Methods ("How ...") fold under their heading; the findings
            // stand in a box. Each takes its part up to the next heading of
            // its level or above.
            let fold = text.starts_with("How ");
            if fold || (level == 2 && text == "Findings") {
                let end = (i + 1..lines.len())
                    .find(|&j| heading(lines[j]).is_some_and(|(l, _)| l <= level))
                    .unwrap_or(lines.len());
                let inner = blocks(&lines[i + 1..end].join("\n"), out_dir, anchors);
                html += &if fold {
                    format!(
                        "<details class=\"methods\"><summary>{h}</summary>\n{inner}</details>\n"
                    )
                } else {
                    format!("<section class=\"findings\">\n{h}{inner}</section>\n")
                };
                i = end;
            } else {
                html += &h;
                i += 1;
            }
        } else if t.starts_with('|') {
            let end = (i..lines.len())
                .find(|&j| !lines[j].trim().starts_with('|'))
                .unwrap_or(lines.len());
            let rows = end - i;
            let table = table(&lines[i..end]);
            html += &if rows > LONG + 2 {
                format!(
                    "<details class=\"long\"><summary>Show the table ({} rows)</summary>\n\
                     <input type=\"search\" class=\"filter\" placeholder=\"Show only rows containing…\" \
                     aria-label=\"Show only rows containing\">\n{table}</details>\n",
                    rows - 2
                )
            } else {
                table
            };
            i = end;
        } else if quoted(t).is_some() {
            // The seeds' own words: a quote, its lines rendered as a body.
            let end = (i..lines.len())
                .find(|&j| quoted(lines[j].trim()).is_none())
                .unwrap_or(lines.len());
            let inner: Vec<&str> = lines[i..end]
                .iter()
                .map(|l| quoted(l.trim()).unwrap_or(""))
                .collect();
            html.push_str("<blockquote>\n");
            html.push_str(&blocks(&inner.join("\n"), out_dir, anchors));
            html.push_str("</blockquote>\n");
            i = end;
        } else if let Some((ordered, _)) = list_item(t) {
            let end = (i..lines.len())
                .find(|&j| list_item(lines[j].trim()).is_none_or(|(o, _)| o != ordered))
                .unwrap_or(lines.len());
            let tag = if ordered { "ol" } else { "ul" };
            html.push_str(&format!("<{tag}>\n"));
            for l in &lines[i..end] {
                let text = list_item(l.trim()).map_or("", |(_, s)| s);
                html.push_str(&format!("<li>{}</li>\n", inline(text)));
            }
            html.push_str(&format!("</{tag}>\n"));
            i = end;
        } else if let Some((caption, file)) = image(t) {
            html.push_str(&figure(caption, file, out_dir));
            i += 1;
        } else {
            para.push(t);
            i += 1;
        }
    }
    flush(&mut html, &mut para);
    html
}

fn flush(html: &mut String, para: &mut Vec<&str>) {
    if !para.is_empty() {
        html.push_str(&format!("<p>{}</p>\n", inline(&para.join(" "))));
        para.clear();
    }
}

/// A quoted line's text: "> text", or ">" alone (a paragraph break).
fn quoted(t: &str) -> Option<&str> {
    t.strip_prefix('>')
        .map(|rest| rest.strip_prefix(' ').unwrap_or(rest))
}

/// (ordered, text) for "- x", "* x" or "12. x".
fn list_item(t: &str) -> Option<(bool, &str)> {
    if let Some(rest) = t.strip_prefix("- ").or_else(|| t.strip_prefix("* ")) {
        return Some((false, rest));
    }
    let digits = t.chars().take_while(char::is_ascii_digit).count();
    let rest = t.get(digits..)?.strip_prefix(". ")?;
    (digits > 0).then_some((true, rest))
}

/// (caption, file) for a line that is exactly `![caption](file)`.
fn image(t: &str) -> Option<(&str, &str)> {
    let inner = t.strip_prefix("![")?.strip_suffix(')')?;
    let (caption, file) = inner.split_once("](")?;
    (!file.contains(['(', ')', ' '])).then_some((caption, file))
}

/// An inlined SVG figure, or a visible note when the file is not a local SVG.
fn figure(caption: &str, file: &str, out_dir: &Path) -> String {
    let local = !file.contains("://") && !file.starts_with('/') && !file.contains("..");
    let svg = if local && file.ends_with(".svg") {
        std::fs::read_to_string(out_dir.join(file))
            .ok()
            .map(|s| inline_svg(&s))
    } else {
        None
    };
    let content = svg.unwrap_or_else(|| {
        format!(
            "<p><em>(figure {} is not an SVG in the report folder)</em></p>",
            escape(file)
        )
    });
    format!(
        "<figure>\n{content}\n<figcaption>{}</figcaption>\n</figure>\n",
        inline(caption)
    )
}

/// SVG markup fit to sit inside HTML: the XML prolog and doctype dropped, and
/// the namespace attribute too (HTML's parser supplies it, and it is the only
/// URL a plotters SVG carries).
pub fn inline_svg(svg: &str) -> String {
    let start = svg.find("<svg").unwrap_or(0);
    svg[start..]
        .replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1)
        .trim()
        .to_string()
}

fn table(rows: &[&str]) -> String {
    let cells: Vec<Vec<String>> = rows.iter().map(|r| split_row(r)).collect();
    let is_rule = |r: &Vec<String>| {
        !r.is_empty()
            && r.iter()
                .all(|c| !c.is_empty() && c.chars().all(|ch| "-:".contains(ch)))
    };
    let (head, align, body) = match cells.get(1) {
        Some(rule) if is_rule(rule) => (Some(&cells[0]), rule.clone(), &cells[2..]),
        _ => (None, Vec::new(), &cells[..]),
    };
    let class = |i: usize| {
        if align
            .get(i)
            .is_some_and(|a| a.ends_with(':') && !a.starts_with(':'))
        {
            " class=\"num\""
        } else {
            ""
        }
    };
    // A wide table scrolls inside its own box; the page never scrolls sideways.
    let mut html = String::from("<div class=\"scroll\"><table>\n");
    if let Some(head) = head {
        html.push_str("<thead><tr>");
        for (i, c) in head.iter().enumerate() {
            html.push_str(&format!("<th{}>{}</th>", class(i), inline(c)));
        }
        html.push_str("</tr></thead>\n");
    }
    html.push_str("<tbody>\n");
    for row in body {
        html.push_str("<tr>");
        for (i, c) in row.iter().enumerate() {
            html.push_str(&format!("<td{}>{}</td>", class(i), inline(c)));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody>\n</table></div>\n");
    html
}

/// Cells of a pipe-table row; `\|` is a literal pipe (kept escaped for `inline`).
fn split_row(row: &str) -> Vec<String> {
    let t = row.trim();
    let t = t.strip_prefix('|').unwrap_or(t);
    let t = if t.ends_with('|') && !t.ends_with("\\|") {
        &t[..t.len() - 1]
    } else {
        t
    };
    let mut cells = Vec::new();
    let mut current = String::new();
    let mut chars = t.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                chars.next();
                current.push_str("\\|");
            }
            '|' => cells.push(std::mem::take(&mut current)),
            c => current.push(c),
        }
    }
    cells.push(current);
    cells.into_iter().map(|c| c.trim().to_string()).collect()
}

/// Inline markup. Text is escaped as it is copied, so no input can open a tag.
pub fn inline(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let (mut strong, mut em) = (false, false);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        match c {
            '\\' if next.is_some_and(|n| n.is_ascii_punctuation()) => {
                out.push_str(&escape(&next.unwrap_or(' ').to_string()));
                i += 2;
            }
            '`' => match chars[i + 1..].iter().position(|&x| x == '`') {
                Some(len) => {
                    let code: String = chars[i + 1..i + 1 + len].iter().collect();
                    out.push_str(&format!("<code>{}</code>", escape(&code)));
                    i += len + 2;
                }
                None => {
                    out.push('`');
                    i += 1;
                }
            },
            '*' if next == Some('*') => {
                out.push_str(if strong { "</strong>" } else { "<strong>" });
                strong = !strong;
                i += 2;
            }
            '*' if next.is_some_and(|n| !n.is_whitespace()) || em => {
                out.push_str(if em { "</em>" } else { "<em>" });
                em = !em;
                i += 1;
            }
            '[' | '!' => match link(&chars[i..]) {
                Some((label, url, used)) => {
                    out.push_str(&link_html(&label, &url));
                    i += used;
                }
                None => {
                    out.push_str(&escape(&c.to_string()));
                    i += 1;
                }
            },
            c => {
                out.push_str(&escape(&c.to_string()));
                i += 1;
            }
        }
    }
    if em {
        out.push_str("</em>");
    }
    if strong {
        out.push_str("</strong>");
    }
    out
}

/// `[label](url)` or `![label](url)` at the start of `chars`: (label, url, chars used).
fn link(chars: &[char]) -> Option<(String, String, usize)> {
    let skip = usize::from(chars.first() == Some(&'!'));
    if chars.get(skip) != Some(&'[') {
        return None;
    }
    let close = chars[skip..].iter().position(|&c| c == ']')? + skip;
    if chars.get(close + 1) != Some(&'(') {
        return None;
    }
    let end = chars[close..].iter().position(|&c| c == ')')? + close;
    let label: String = chars[skip + 1..close].iter().collect();
    let url: String = chars[close + 2..end].iter().collect();
    Some((label, url, end + 1))
}

/// Links to files beside the report stay links; a web address is shown as
/// text, because the page promises to fetch nothing from outside.
fn link_html(label: &str, url: &str) -> String {
    if url.contains(':') || url.starts_with("//") {
        format!("{} ({})", inline(label), escape(url))
    } else {
        format!("<a href=\"{}\">{}</a>", escape(url), inline(label))
    }
}

pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_markup_is_escaped() {
        assert_eq!(
            inline("a <b> & `x<y` **z** *w*"),
            "a &lt;b&gt; &amp; <code>x&lt;y</code> <strong>z</strong> <em>w</em>"
        );
        assert_eq!(inline("2 * 3"), "2 * 3");
        assert_eq!(
            inline("[runs](runs.parquet)"),
            "<a href=\"runs.parquet\">runs</a>"
        );
    }

    #[test]
    fn tables_and_lists() {
        let md = "| a | b |\n|---|--:|\n| x \\| y | 2 |\n\n- one\n- two\n";
        let html = body(md, Path::new("."));
        assert!(html.contains("<th>a</th><th class=\"num\">b</th>"));
        assert!(html.contains("<td>x | y</td>"));
        assert!(html.contains("<ul>\n<li>one</li>\n<li>two</li>\n</ul>"));
    }

    #[test]
    fn quotes_are_blockquotes() {
        let md = "> What would happen\n> if *walls* were warmer?\n>\n> Second.\n\nAfter.";
        let html = body(md, Path::new("."));
        assert_eq!(
            html,
            "<blockquote>\n<p>What would happen if <em>walls</em> were warmer?</p>\n<p>Second.</p>\n</blockquote>\n<p>After.</p>\n"
        );
    }
}
