// SPDX-License-Identifier: MIT
// satviz app: the lessons of tutorials/ as the app shows them: found on disk, parsed from Markdown with md4c into
// blocks of text, headings, list items, code and figures, marked when they lie in a quote or a <details>
// section. No drawing here (see Panels::LessonWindow).
#pragma once

#include <string>
#include <vector>

namespace satviz
{

/// A lesson file of tutorials/ (NN-slug.md).
struct Lesson
{
    std::string file;                ///< path of the Markdown file
    std::string title;               ///< its first heading, without the "#"
    /// The scene files of its figures and those its text names (tutorials/scenes/NAME.json, scenes/concave/NAME.json),
    /// in order of first mention, no repeats, except that the scene of its first figure comes first.
    std::vector<std::string> scenes;
    /// The step its first figure shows (FigureStep), which the lesson opens its first scene on; -1 for the scene's own.
    int firstStep = -1;
    /// True when its first figure shows the face tests (figures/faces/), which the lesson opens its first scene in.
    bool firstFaces = false;
};

/// The scenes a lesson's text names ("scenes/NAME.json", "scenes/concave/NAME.json"), as NAME ("concave/NAME"), in
/// order of first mention, no repeats.
std::vector<std::string> NamedScenes(const std::string& markdown);

/// The scene a figure was rendered from: "figures/faces/overlapping_boxes-step6.png" -> "overlapping_boxes".
std::string SceneOfFigure(const std::string& figure);

/// The step of the textbook test a figure shows, from 0: "overlapping_boxes-step6.png" -> 5; -1 for a figure without
/// "-stepN", which shows the step its scene's view asks for.
int FigureStep(const std::string& figure);

/// True for a figure of the face tests' steps (figures/faces/NAME-stepN.png, satviz-render --view faces).
bool FigureOfFaces(const std::string& figure);

/// The scene file a figure of the lessons in `folder` was rendered from: `folder`/scenes/NAME.json or, failing that,
/// NAME.json in a folder of scenes/ (scenes/concave/), NAME as SceneOfFigure gives it; empty when there is none.
std::string FigureSceneFile(const std::string& folder, const std::string& figure);

/// The lessons in `folder` (files named NN-slug.md), in order; empty when there are none or the folder is missing.
std::vector<Lesson> FindLessons(const std::string& folder);

/// One block of a lesson as the app's panel lays it out.
struct LessonBlock
{
    /// What the block is.
    enum class Kind
    {
        Heading,   ///< a heading of `level` 1 to 6
        Paragraph, ///< running text
        Item,      ///< a list item, `level` deep (1 for the outer list)
        Code,      ///< a code block, shown as it is
        Figure,    ///< an image: `text` is its alternative text, `target` its file
        Rule,      ///< a horizontal rule
    };
    Kind kind = Kind::Paragraph; ///< what the block is
    int level = 0;               ///< heading level or list depth
    /// An item of a numbered list: its number as the list counts it (from the list's start); 0 for a bullet item.
    int number = 0;
    std::string text;            ///< the block's text, inline markup flattened (links keep their text)
    std::string target;          ///< a figure's file, relative to the lesson
    /// The block lies in a block quote (the lessons' "> **In satviz.**" boxes of implementation detail): the panel
    /// draws it in a marked box, apart from the method.
    bool quote = false;
    /// The block lies in the n-th `<details>` section of the lesson (1, 2, ...; 0 outside one): the panel shows it
    /// collapsed under `summary` until the student opens it (the exercises' answers).
    int details = 0;
    std::string summary; ///< the `<summary>` text of that section ("Answers")
    /// A row of a table (a Paragraph whose `text` is its cells joined by " | "): its cells' texts, empty otherwise.
    std::vector<std::string> cells;
    bool header = false; ///< the row is the table's heading row
};

/// Parses a lesson's Markdown (CommonMark with tables, as md4c reads it) into blocks. HTML comments (the lessons'
/// check marks) are dropped; a table becomes one paragraph per row, its cells separated by " | ". Blocks of a
/// block quote are marked `quote`; those between `<details><summary>S</summary>` and `</details>` carry the
/// section's number and S, which is not a block of its own.
std::vector<LessonBlock> ParseLesson(const std::string& markdown);

/// Reads and parses a lesson file; false with a one-line error naming the file when it cannot be read.
bool LoadLesson(const std::string& file, std::vector<LessonBlock>& blocks, std::string& error);

} // namespace satviz
