//! The document's content read, and changed only through named
//! operations: what each one changes is in its name, and
//! [`CharacterDoc::validate`] (run by every save and build) checks the
//! result.

use super::{CharacterDoc, Continuity, Inputs, KeySection, PartSpec, RemovedPart, TransitionSpec};
use crate::character::props::PropSpec;

/// Reading the inputs and the derived content.
impl CharacterDoc {
    /// What the character is derived from: the drawings, key sections,
    /// tolerance, height and body plan.
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }

    /// The stored parts: derived from the inputs at the document's level
    /// (empty until the first build derives them), the edit log not
    /// applied.
    pub fn parts(&self) -> &[PartSpec] {
        &self.parts
    }

    /// The stored transitions between the parts (derived with them).
    pub fn transitions(&self) -> &[TransitionSpec] {
        &self.transitions
    }

    /// The parts drawn separately (each one's spec is among
    /// [`Self::parts`] once built).
    pub fn removed_parts(&self) -> &[RemovedPart] {
        &self.removed_parts
    }

    /// The props: conv models composed as separate components.
    pub fn props(&self) -> &[PropSpec] {
        &self.props
    }
}

/// Constructing a document with content and changing its content.
impl CharacterDoc {
    /// Stores `parts` and `transitions` as the document's derived content
    /// in place of the stored ones (what a build derived from the inputs;
    /// the parts of the removed parts included). The edit log is kept: it
    /// acts on the stored parts by name.
    pub fn set_derived(&mut self, parts: Vec<PartSpec>, transitions: Vec<TransitionSpec>) {
        self.parts = parts;
        self.transitions = transitions;
    }

    /// The stored part named `name`, to change in place (an editor's or a
    /// template's change of a stored part; an edit of the log never
    /// changes it). `None` when there is no such part.
    pub fn part_mut(&mut self, name: &str) -> Option<&mut PartSpec> {
        self.parts.iter_mut().find(|p| p.name == name)
    }

    /// The stored transition named `name`, to change in place (its
    /// continuity, tangent scale or cut angles). `None` when there is no
    /// such transition.
    pub fn transition_mut(&mut self, name: &str) -> Option<&mut TransitionSpec> {
        self.transitions.iter_mut().find(|t| t.name == name)
    }

    /// Sets the continuity of every stored transition to the parts (`C2`
    /// is the quintic Hermite blend, `C1` the cubic one).
    pub fn set_continuity(&mut self, continuity: Continuity) {
        for t in &mut self.transitions {
            t.continuity = continuity;
        }
    }

    /// Records a separately drawn part (an input). It is built into a part
    /// when the parts are derived (a build of a document without stored
    /// parts, or with `rederive`); until then the report lists it as not
    /// built. [`Self::add_drawn_part`] records and stores the built part at
    /// once.
    pub fn push_removed_part(&mut self, removed: RemovedPart) {
        self.removed_parts.push(removed);
    }

    /// Adds a separately drawn part: its drawing (`removed`, an input) and
    /// the part built from it (`spec`, appended to the stored parts).
    pub fn add_drawn_part(&mut self, removed: RemovedPart, spec: PartSpec) {
        self.removed_parts.push(removed);
        self.parts.push(spec);
    }

    /// Adds the key section `k` to the inputs and stores `parts`, the
    /// stored parts with `k` applied.
    pub fn add_key_section(&mut self, k: KeySection, parts: Vec<PartSpec>) {
        self.inputs.sections.push(k);
        self.parts = parts;
    }

    /// Attaches the prop `p` (appended to the props).
    pub fn push_prop(&mut self, p: PropSpec) {
        self.props.push(p);
    }

    /// Detaches the prop named `name` and returns it (`None`, the document
    /// unchanged, when there is no such prop).
    pub fn remove_prop(&mut self, name: &str) -> Option<PropSpec> {
        let i = self.props.iter().position(|p| p.name == name)?;
        Some(self.props.remove(i))
    }

    /// Puts back the inputs and every derived field as they were (an
    /// undo or redo of a command that changed them); the edit log is left
    /// alone.
    pub fn restore_content(
        &mut self,
        inputs: Inputs,
        parts: Vec<PartSpec>,
        transitions: Vec<TransitionSpec>,
        removed_parts: Vec<RemovedPart>,
        props: Vec<PropSpec>,
    ) {
        self.inputs = inputs;
        self.parts = parts;
        self.transitions = transitions;
        self.removed_parts = removed_parts;
        self.props = props;
    }
}
