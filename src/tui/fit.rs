//! Lines that fit the screen: long paths (a deep checkout or temp
//! directory) give way from their start, so the point of a message, a
//! prompt's error or a panel's value stays on its line.

/// `text` cut to at most `max` characters by dropping its start (marked
/// with an ellipsis).
pub fn elide_left(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_string();
    }
    if max == 0 {
        return String::new();
    }
    let keep = max - 1;
    let mut out = String::from("…");
    out.extend(text.chars().skip(n - keep));
    out
}

/// Characters of a path kept when a line is made to fit.
const PATH_MIN_SHOWN: usize = 12;

/// `text` made to fit `max` characters: its path-like words (with a `/`),
/// longest first, lose their start (the file name stays), down to
/// [`PATH_MIN_SHOWN`] characters each; what is still too long loses its
/// end (marked with an ellipsis). Long checkout or temp directories must
/// not push a message's point off its line.
pub fn fit(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_string();
    }
    let mut words: Vec<String> = text.split(' ').map(String::from).collect();
    let mut over = n - max;
    let mut paths: Vec<usize> = (0..words.len())
        .filter(|&i| words[i].contains('/') || words[i].contains('\\'))
        .collect();
    paths.sort_by_key(|&i| std::cmp::Reverse(words[i].chars().count()));
    for i in paths {
        let len = words[i].chars().count();
        let cut = over.min(len.saturating_sub(PATH_MIN_SHOWN));
        if cut > 0 {
            words[i] = elide_left(&words[i], len - cut);
            over -= cut;
        }
        if over == 0 {
            return words.join(" ");
        }
    }
    elide_right(&words.join(" "), max)
}

/// `text` cut to at most `max` characters by dropping its end.
pub fn elide_right(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        return text.to_string();
    }
    let mut out: String = text.chars().take(max.saturating_sub(1)).collect();
    if max > 0 {
        out.push('…');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{elide_left, fit};

    #[test]
    fn elide_left_keeps_the_end_within_the_width() {
        assert_eq!(elide_left("abc", 3), "abc");
        assert_eq!(elide_left("/a/long/path.json", 10), "…path.json");
        assert_eq!(elide_left("/a/long/path.json", 10).chars().count(), 10);
        assert_eq!(elide_left("ééééé", 2), "…é");
        assert_eq!(elide_left("abc", 0), "");
    }

    #[test]
    fn fit_shortens_paths_first_then_the_end() {
        let long = format!("/{}/char.json", "d".repeat(200));
        let t = fit(&format!("saved {long} ok"), 40);
        assert_eq!(t.chars().count(), 40);
        assert!(
            t.starts_with("saved …") && t.ends_with("/char.json ok"),
            "{t}"
        );
        // no path: the end goes
        let t = fit(&"x".repeat(50), 10);
        assert_eq!(t, format!("{}…", "x".repeat(9)));
        assert_eq!(fit("short", 10), "short");
        // paths keep their last characters, then the end goes
        let t = fit(&format!("{long} {long} tail"), 20);
        assert_eq!(t.chars().count(), 20);
        assert!(t.starts_with('…'), "{t}");
    }
}
