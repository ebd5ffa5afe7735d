//! The preview through the kitty terminal graphics protocol, where the
//! terminal says it has it (`$KITTY_WINDOW_ID` set, or `$TERM` naming
//! kitty): the rasteriser's image at [`CELL_PX`] pixels per cell, sent as
//! PNG (`f=100`) in base64 chunks of at most [`CHUNK`] bytes, placed over
//! the preview's cells (`c`, `r`) with one fixed image id, so sending it
//! again replaces it. The half-block preview is still drawn below it (what
//! every other terminal shows). A popup over the preview removes the image
//! until it closes.
//!
//! The escape sequences are built here as strings (tested); the event loop
//! writes them after ratatui's draw (`term::run`).

/// Pixels per terminal cell of the image sent (the terminal scales it).
pub const CELL_PX: (u16, u16) = (8, 16);
/// Most base64 bytes in one escape sequence (the protocol's limit).
pub const CHUNK: usize = 4096;
/// The preview's image id.
pub const IMAGE_ID: u32 = 1414;

/// Whether the terminal announces the kitty graphics protocol.
pub fn supported(term: Option<&str>, kitty_window_id: Option<&str>) -> bool {
    kitty_window_id.is_some_and(|w| !w.is_empty()) || term.is_some_and(|t| t.contains("kitty"))
}

/// [`supported`] for this process's environment.
pub fn detect() -> bool {
    let term = std::env::var("TERM").ok();
    let win = std::env::var("KITTY_WINDOW_ID").ok();
    supported(term.as_deref(), win.as_deref())
}

/// Standard base64 with padding.
pub fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let b = [c[0], *c.get(1).unwrap_or(&0), *c.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= c.len() {
                out.push(A[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Removes the preview's image.
pub fn clear() -> String {
    format!("\x1b_Ga=d,d=I,i={IMAGE_ID},q=2\x1b\\")
}

/// Places `png` over the `cols x rows` cells whose top-left cell is
/// (`x`, `y`) (0-based): the cursor is saved, moved there and restored; the
/// image replaces the previous one (same id); no replies (`q=2`).
pub fn place(png: &[u8], x: u16, y: u16, cols: u16, rows: u16) -> String {
    let data = base64(png);
    let chunks: Vec<&str> = data
        .as_bytes()
        .chunks(CHUNK)
        .map(|c| std::str::from_utf8(c).unwrap_or(""))
        .collect();
    let mut out = format!("\x1b7\x1b[{};{}H", y + 1, x + 1);
    out.push_str(&clear());
    let n = chunks.len().max(1);
    for i in 0..n {
        let more = u8::from(i + 1 < n);
        let chunk = chunks.get(i).copied().unwrap_or("");
        if i == 0 {
            out.push_str(&format!(
                "\x1b_Ga=T,f=100,i={IMAGE_ID},c={cols},r={rows},C=1,q=2,m={more};{chunk}\x1b\\"
            ));
        } else {
            out.push_str(&format!("\x1b_Gm={more};{chunk}\x1b\\"));
        }
    }
    out.push_str("\x1b8");
    out
}
