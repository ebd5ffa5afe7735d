//! The commands a prompt line is for.

/// Which command a prompt is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PromptKind {
    AddPart,
    KeySection,
    AddProp,
}

impl PromptKind {
    /// Shown before the typed text.
    pub fn label(self) -> &'static str {
        match self {
            PromptKind::AddPart => "add part from profile: ",
            PromptKind::KeySection => "key section: ",
            PromptKind::AddProp => "attach prop: ",
        }
    }

    /// What to type.
    pub fn hint(self) -> &'static str {
        match self {
            PromptKind::AddPart => "PATH.svg [NAME] (outline in model units; Tab completes)",
            PromptKind::KeySection => "Y A B (ellipse) | Y FILE.json (closed curve)",
            PromptKind::AddProp => "MODEL.json [NAME [SCALE [TX TY TZ]]] (conv model)",
        }
    }
}
