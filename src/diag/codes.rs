//! The table of diagnostic codes: code, kebab-case name, default severity
//! and the explanation `cncc explain` prints. Codes are stable: a code is
//! never reused for another meaning.
//!
//! Ranges: E00xx reading characters and numbers, E01xx syntax, E02xx words
//! and modal groups of a block, E03xx program structure and jumps, E04xx
//! dialect specs, E05xx running the program, E06xx writing to a target,
//! E10xx the material simulation ([`crate::sim`]);
//! W-codes are warnings. W07xx are the lint rules ([`crate::lint`]):
//! mistakes a controller runs without complaint but that break tools or
//! crash spindles; each is a warning a shop selects or ignores by code,
//! prefix or name (`cncc.toml`, `--select`, `--ignore`).

use super::Severity;

macro_rules! codes {
    ($( $variant:ident = $code:literal, $name:literal, $sev:ident, $summary:literal, $explain:literal; )*) => {
        /// A stable diagnostic code.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Code { $( $variant, )* }

        impl Code {
            pub const ALL: &'static [Code] = &[ $( Code::$variant, )* ];

            /// `E0201`.
            pub fn code(self) -> &'static str {
                match self { $( Code::$variant => $code, )* }
            }

            /// `two-motion-codes`.
            pub fn name(self) -> &'static str {
                match self { $( Code::$variant => $name, )* }
            }

            pub fn severity(self) -> Severity {
                match self { $( Code::$variant => Severity::$sev, )* }
            }

            /// One line saying what the code is about.
            pub fn summary(self) -> &'static str {
                match self { $( Code::$variant => $summary, )* }
            }

            /// What it means and what to do, for `cncc explain`.
            pub fn explanation(self) -> &'static str {
                match self { $( Code::$variant => $explain, )* }
            }
        }
    };
}

codes! {
    UnclosedComment = "E0001", "unclosed-comment", Error,
        "a comment opened with `(` is not closed on its line",
        "A parenthesised comment must close on the line it opens on. A comment that never closes would swallow the rest of the block, so the opening parenthesis is reported. Close it with `)`.";
    NestedComment = "E0006", "nested-comment", Error,
        "a `(` inside a parenthesised comment",
        "LinuxCNC does not nest comments: a `(` before the comment's `)` stops the program with \"Nested comment found\". cncc reports it once for the line and reads that line no further, so the comment's text is not taken for words. Remove the inner parentheses (or use [ ]).";
    BadCharacter = "E0002", "bad-character", Error,
        "a character that has no meaning in this dialect",
        "The character is not a word address, operator, or part of a number, comment or string in this dialect. Remove it, or put it inside a comment.";
    MalformedNumber = "E0003", "malformed-number", Error,
        "a number that cannot be read, such as `1.2.3`",
        "A number has at most one decimal point and only digits besides. Check for a doubled point or a missing word address between two numbers.";
    UnterminatedString = "E0004", "unterminated-string", Error,
        "a string that is not closed on its line",
        "A string opened with `\"` must close on the same line.";
    NumberTooLong = "E0005", "number-too-long", Error,
        "a number with more digits than can be kept exactly",
        "cncc keeps numbers exactly as decimals of up to 18 significant digits. Controllers accept far fewer; shorten the number.";
    SyntaxError = "E0101", "syntax-error", Error,
        "the words of a block do not form a valid statement",
        "The parser met a token it did not expect here. The message names what was found and what could come instead.";
    IncompleteExpression = "E0102", "incomplete-expression", Error,
        "an expression ends before it is complete",
        "An expression is missing an operand, a closing bracket or a closing parenthesis. Complete it.";
    WordWithoutValue = "E0103", "word-without-value", Error,
        "a word address with no value after it",
        "Every word is a letter followed by a number or an expression, as in `F100`. A letter alone has no meaning.";
    UnknownKeyword = "E0104", "unknown-keyword", Error,
        "a keyword or name this dialect does not know",
        "The name is not a keyword, function, cycle, variable or subprogram this dialect knows. Check its spelling, or declare it.";
    UnbracketedExpression = "E0105", "unbracketed-expression", Error,
        "arithmetic after a word without brackets",
        "In this dialect a word takes a number, a variable or a bracketed expression: write `X[#1/2]`, not `X#1/2`.";
    NotInDialect = "E0106", "not-in-dialect", Error,
        "a construct this dialect does not have",
        "The construct (Macro B `IF`/`WHILE`/`GOTO`, LinuxCNC o-words, `#<name>` parameters, `**`, `O1234` program numbers, `#` variables) belongs to another dialect. Choose the dialect the program was written for with `--dialect`, or rewrite the construct.";
    TwoMotionCodes = "E0201", "two-motion-codes", Error,
        "two motion codes (G0, G1, G2, G3, cycles) in one block",
        "A block can ask for one motion only. Split the block, or remove one of the codes.";
    ModalGroupConflict = "E0202", "modal-group-conflict", Error,
        "two codes of one modal group in one block",
        "Codes of one modal group exclude each other (G90 and G91, G17 and G18, M3 and M4). Keep one per block.";
    UnknownGCode = "E0203", "unknown-g-code", Error,
        "a G code this dialect does not have",
        "The G code is not in this dialect's code table. Check the number, or load a dialect spec that defines it with `--dialect-file`.";
    UnknownMCode = "E0204", "unknown-m-code", Error,
        "an M code this dialect does not have",
        "The M code is not in this dialect's code table. Machine builders add M codes; describe yours in a dialect spec loaded with `--dialect-file`.";
    RepeatedWord = "E0205", "repeated-word", Error,
        "the same word address twice in one block",
        "A block can hold each word address once (except G and M, which may repeat across modal groups). Remove one of the words.";
    MissingWord = "E0206", "missing-word", Error,
        "a code without a word it requires",
        "Some codes need a word to act on: G4 its dwell time, G83 its peck depth Q, G2/G3 a centre or radius. Add the word.";
    MixedArcFormat = "E0207", "mixed-arc-format", Error,
        "an arc given both a radius and a centre",
        "An arc is given either by its radius (R, CR=) or by its centre (I, J, K), not both. Remove one.";
    UnknownAddress = "E0208", "unknown-address", Error,
        "a word address this dialect does not have",
        "The letter is not an address this dialect reads. Check the spelling, or put the text in a comment.";
    WordNotAllowed = "E0209", "word-not-allowed", Error,
        "a word that the block's codes cannot use",
        "The word has no code in this block that uses it (for example axis words with G80). Remove it or add the code that uses it.";
    NegativeValue = "E0210", "negative-value", Error,
        "a negative value where only positive ones have meaning",
        "Feed rates, spindle speeds, dwell times and peck depths are never negative.";
    CycleTooManyArguments = "E0211", "cycle-too-many-arguments", Error,
        "a cycle call with more arguments than its signature has",
        "The cycle's signature in the dialect spec lists fewer parameters than the call gives. Newer controller versions append parameters; if yours does, extend the cycle's signature in a dialect spec.";
    CycleArgumentKind = "E0212", "cycle-argument-kind", Error,
        "a cycle argument of the wrong kind",
        "The parameter takes a number, an integer or a string, and the argument is of another kind.";
    InvalidValue = "E0213", "invalid-value", Error,
        "a value outside the range its word allows",
        "The value is out of the range that the code accepts (for example a G10 L2 P word above 9, or a non-integer G code).";
    JumpTargetMissing = "E0301", "jump-target-missing", Error,
        "a jump or call to a block number or label that does not exist",
        "GOTO, M99 P, M97 P and GOTOF/GOTOB name a sequence number or label that must exist in the program (searched in the direction the jump says). Add the label, or correct the target.";
    UnbalancedBlock = "E0302", "unbalanced-block", Error,
        "a control-flow block opened but not closed, or closed but not opened",
        "IF/ENDIF, WHILE/ENDWHILE (END m), FOR/ENDFOR, REPEAT/UNTIL, LOOP/ENDLOOP, and O-word sub/endsub, if/endif, while/endwhile, do/while, repeat/endrepeat pair up. Add the missing partner.";
    MismatchedEnd = "E0303", "mismatched-end", Error,
        "a block closed by the end of another",
        "The closing statement does not match the innermost open block (for example `END2` closing `DO1`, or `o101 endwhile` closing `o100 if`).";
    DuplicateLabel = "E0304", "duplicate-label", Error,
        "the same label or subprogram defined twice",
        "A label, O-word subroutine or program number names one place. Rename one of them.";
    NoProgramEnd = "E0305", "no-program-end", Error,
        "the program ends without M2, M30 or a closing %",
        "This dialect requires a program to end with M2 or M30 (or a closing %). Add one.";
    ControlOutsideSub = "E0306", "misplaced-statement", Error,
        "a statement in a place it cannot be",
        "The statement is not allowed here (for example `return` outside a subroutine, `break` outside a loop, DEF after the first executable block).";
    SpecMalformed = "E0401", "spec-malformed-xml", Error,
        "a dialect spec that is not well-formed XML",
        "The dialect spec could not be read as XML. The label points at the place the XML reader stopped.";
    SpecUnknownItem = "E0402", "spec-unknown-item", Error,
        "an element or attribute the dialect schema does not have",
        "The dialect spec uses an element or attribute that `dialects/dialect.xsd` does not define. Check its spelling against the schema.";
    SpecBadValue = "E0403", "spec-bad-value", Error,
        "a value in a dialect spec that cannot be read",
        "An attribute holds a value of the wrong form (a code that is not a number, an unknown meaning, capability or modal group).";
    SpecMissing = "E0404", "spec-missing-item", Error,
        "a required element or attribute missing from a dialect spec",
        "The schema requires this element or attribute. Add it.";
    SpecUnknownBase = "E0405", "spec-unknown-base", Error,
        "a dialect spec extending a dialect that does not exist",
        "`extends` names a dialect id or alias that is neither built in nor loaded. Built-in ids: fanuc, haas, linuxcnc, siemens840d.";
    SpecDuplicate = "E0406", "spec-duplicate", Error,
        "the same code or cycle defined twice in one dialect spec",
        "A code or cycle is defined twice in one file. Remove one; to change an inherited entry, define it once in the extending spec.";
    UnknownDialect = "E0407", "unknown-dialect", Error,
        "a dialect name that is neither built in nor loaded",
        "`--dialect` (or `extends`) names no known dialect id or alias, or a dialect cncc cannot read yet (Heidenhain). `cncc dialects` lists the available ones; load your own with `--dialect-file`.";
    CannotExpress = "E0601", "cannot-express", Error,
        "a construct the target dialect cannot express",
        "The target dialect has no form for this construct. Choose another target, or allow a documented fallback where one exists.";
    RawInForeignDialect = "E0602", "raw-in-foreign-dialect", Error,
        "text kept verbatim from one dialect written into another",
        "cncc kept this text as written because it did not understand it. It can be written back only into the dialect it came from.";
    InexactNumber = "E0603", "inexact-number", Error,
        "a number the target dialect cannot write exactly",
        "The value has more decimal places than the target writes (its least input increment), or a conversion (such as a dwell from seconds to whole milliseconds) would not be exact. cncc never rounds silently: round the value in the source, or choose a target spec with more places.";
    PostUnsupported = "E0900", "post-unsupported", Error,
        "a STEP-NC feature, operation or executable the post cannot write for this target",
        "The post-processor has no cycle and no explicit toolpath generator for this combination of feature and operation on the target dialect (or the workplan holds an executable it cannot post). Explicit toolpaths are posted as they are (NIST helices about the tool axis included), except dwells (FEEDSTOP), tool-axis curves and other curves the reader kept raw. A target whose spec does not declare the template a workingstep needs (`<post-template name=\"drill\"/>`) refuses it the same way, naming the target and the template. Choose another target, declare the template (docs/posts.md), or change the feature or operation in the STEP-NC file.";
    PostBadProject = "E0901", "post-bad-project", Error,
        "a STEP-NC project that lacks what posting needs",
        "Posting needs, for each machining workingstep, its feature, operation and tool, a feed and a spindle speed (or what they can be computed from), and planes in a sensible order. The message names the entity and what is missing or inconsistent.";
    PostGeometry = "E0902", "post-geometry", Error,
        "a feature the tool cannot machine as asked",
        "The tool does not fit the feature (diameter against width or corner radius), or the stepover is not between zero and the tool diameter. Choose a smaller tool or change the strategy in the STEP-NC file.";
    PostTemplate = "E0903", "post-template", Error,
        "a post template that fails or drops a value",
        "A template in posts/<dialect>/ asked for a value it was not given, or did not use a value it was given without declaring it in its first line (`{#- unused: name -#}`). This is a bug in the post-processor: please report it.";
    PostReadBack = "E0904", "post-read-back", Error,
        "a posted program that does not read back cleanly",
        "cncc reads every program it posts with the target's own front end before writing it. This one gave an error, shown in the message: a bug in the post-processor or its templates; please report it.";
    PostNoTarget = "E0905", "post-no-target", Error,
        "a target dialect with no post-processor templates",
        "`cncc post` writes with the templates the target's spec declares (`<post-template name=\"drill\"/>`), read from the folder given with --post-dir or from the built-in folder posts/<id>/ of the spec or of a spec it extends. This dialect's spec declares none (iso6983 is a common base, not a machine). Post to siemens840d, fanuc, haas, linuxcnc or heidenhain, or to a spec that extends one of them.";
    PostTapPitch = "E0906", "post-tap-pitch", Error,
        "a tapping operation whose thread pitch cannot be worked out",
        "ISO 14649 gives a TAPPING operation's thread pitch as its technology's feed over its spindle speed (the two synchronised). This operation has no spindle speed, a zero speed, or a feed that gives no positive pitch. Give the MILLING_TECHNOLOGY a feedrate and a spindle speed whose ratio is the pitch (mm per revolution).";
    PostTapHand = "E0907", "post-tap-hand", Error,
        "a tap whose hand contradicts the spindle direction",
        "A right-hand tap cuts turning clockwise (M3, a positive spindle speed in cncc's model; ISO 14649 stores it negative), a left-hand tap counter-clockwise (M4). The TAP tool's hand_of_cut and the operation's spindle speed disagree, so the tapping cycle (G84 or G74, the sign of CYCLE84's PIT or CYCL DEF 207's Q239) cannot be chosen. Make them agree in the STEP-NC file.";
    PostOutsideStock = "E0908", "post-outside-stock", Error,
        "a STEP-NC feature outside the stock, or without depth",
        "Before posting, cncc checks that every feature lies inside the workpiece's BLOCK (the rawpiece's when there is one), placed through the setup and workpiece setup, and goes down from its top. The message gives the feature's box and the stock's, both in machine coordinates, and the likely cause. A profile whose placement repeats its feature's (ISO 14649-10 places profiles in the feature's frame, so the two add) is the usual one: `cncc post --profiles-absolute` reads such profiles as placed at their feature's origin.";
    PostTemplateFile = "E0909", "post-template-file", Error,
        "a declared post template without a file, or a template file the spec does not declare",
        "Every template a dialect spec declares (`<post-template name=\"tap\"/>`) needs its file `tap.j2`: in the folder given with --post-dir, else in the built-in folder posts/<id>/ of the spec or of the nearest spec it extends. A declared template none of them has is an error at its declaration. So is a file in the --post-dir folder that the spec does not declare (or whose name is no post template), since it would never be used: declare it in a spec that extends the target, rename it, or remove it. `cncc dialects --templates ID` writes a target's templates into a folder to start from.";
    ImplausibleFeed = "W0901", "implausible-feed", Warning,
        "a feed that implies an implausible chip load for the tool",
        "The feed over the spindle speed (and the tool's teeth) gives the chip load per tooth (milling) or the feed per revolution (drilling). A value far above what such a tool takes (more than a tenth of its diameter per revolution for a drill, a tenth of its diameter or 1 mm per tooth for a cutter) is usually a unit mistake in the file (feed in mm/s written as m/s). The post goes on; check the technology.";
    ProfilePlacementRepeated = "W0902", "profile-placement-repeated", Warning,
        "a profile placed at its feature's absolute position again",
        "ISO 14649-10 places a feature's profile (and a slot's course of travel) in the feature's own frame. This profile's placement has the same non-zero location as the feature's, which generators that write absolute positions twice produce; cncc reads it as the standard says (the locations add). If the file meant one absolute position, post with `--profiles-absolute`.";
    StockUnknown = "W0903", "stock-unknown", Warning,
        "a STEP-NC workpiece without a BLOCK: features not checked against the stock",
        "The validator checks every feature against the workpiece's BLOCK bounding geometry (or its rawpiece's). This workpiece gives none (or another shape), so nothing says the features lie inside the material: check the placements yourself, or give the WORKPIECE a BLOCK.";
    PostNotCarried = "W0900", "post-not-carried", Warning,
        "a STEP-NC value the target's cycle or toolpath cannot carry",
        "The posted program cannot express this value (a drilling strategy's reduced feeds, a spindle stop at the bottom of a reaming pass...). It is named in a comment in the program at the workingstep it belongs to, so nothing is dropped silently; check whether the machining still meets the plan.";
    AngleRadians = "W0905", "angle-in-radians", Warning,
        "a STEP-NC plane angle read as radians",
        "ISO 14649 gives plane angles (a V profile's angles, a U profile's wall angles, a tool's tip angle) in degrees, but some generators write radians. An angle that is not a whole number of degrees but is one once read as radians (1.5707963267948966 is 90°) is read as radians; the warning names the feature and the attribute. Write the angle in degrees to silence it.";
    SecplaneBelowRetract = "W0904", "secplane-below-retract", Warning,
        "a workingstep's security plane below its operation's retract plane",
        "ISO 14649-10 gives a workingstep's security plane and its operation's retract_plane both in the feature's frame: the tool approaches from the retract plane at cutting feed and may rapid only above it, and the security plane is where rapids are safe. Here the security plane lies below the retract plane, so the file contradicts itself. The post does not refuse it: it makes its rapids at the retract plane (the higher of the two, the safe choice) and goes on. Raise the security plane or lower the retract_plane in the STEP-NC file.";
    FeaturesMismatch = "E0940", "features-mismatch", Error,
        "a ported program whose features differ from the source's",
        "`cncc port --features --verify` raises the posted program to STEP-NC CC2 again and compares its features, operations, tools and workingsteps with those raised from the source (by meaning: ids and instance numbers aside). The message names the first difference; the port is not written. The expanded toolpaths are not compared.";
    PortCycle = "E0610", "port-cycle", Error,
        "a canned cycle the target has no equivalent for",
        "`cncc port` maps drilling cycles to the target's own cycles (G81..G89 to CYCLE81..CYCLE89 and back). This cycle, or this combination of its words, has no equivalent that cuts the same way in the target. Allow the documented fallback `--expand-cycles` to write the cycle as the moves it makes.";
    PortCycleBlock = "E0611", "port-cycle-block", Error,
        "a block in a modal cycle that does more than position the next hole",
        "While a canned cycle (or an MCALL) is in force, `cncc port` carries blocks that give only the next hole position (X, Y). A block that also changes the depth, another axis or the cycle's words there cannot be carried one-to-one. Cancel the cycle (G80 / MCALL) and start it again with the new words, or use `--expand-cycles`.";
    PortRunTimeValue = "E0612", "port-run-time-value", Error,
        "a cycle parameter the port needs but that is known only at run time",
        "Mapping a cycle computes some parameters from the modal state (the initial level for G98, the feed and speed for a tapping pitch, sums of planes). Here a value it needs is an expression, incremental, or not set before the cycle. Give the value as a number before the cycle, use G99, or use `--expand-cycles`.";
    PortVariable = "E0613", "port-variable", Error,
        "a variable the target has no equivalent for",
        "Numbered variables map one-to-one: Fanuc/Haas/LinuxCNC `#n` to Siemens `Rn` and back, when the target has that number. Named and declared variables, and numbers outside the target's ranges, cannot be carried; rename them to numbered variables in the source.";
    PortControlFlow = "E0614", "port-control-flow", Error,
        "a control-flow structure the target cannot express",
        "Loops and conditionals are written in the target's own form (Fanuc WHILE [..] DO1 / END1, Siemens WHILE / ENDWHILE, LinuxCNC o-words). This one has no form in the target (for example more than three nested Fanuc DO loops, or an IF block in Fanuc Macro B). Rewrite it with jumps, or choose another target.";
    BadToolMap = "E0615", "bad-tool-map", Error,
        "a tool map that cannot be read",
        "`--tool-map` takes pairs `OLD=NEW` separated by commas (`1=5,2=7`) or a file with one pair per line (`#` starts a comment). Tool numbers are whole and not negative; each old number appears once.";
    VerifyMismatch = "E0616", "verify-mismatch", Error,
        "the ported program does not cut the same as the source",
        "`cncc port --verify` runs both programs and compares their cutting moves (feed moves and arcs, within 1 micrometre, with their feed rates). The first difference is shown with the statement in each program. Rapids are compared too, from the first move to the last: a rapid below the highest cutting height that is not the same on both sides fails the verification (except the approach after a tool change or a move in machine coordinates, and a vertical rapid inside a place already cut deeper, such as a peck's retract).";
    PortSubprogram = "E0617", "port-subprogram", Error,
        "a subprogram call the port cannot carry to the target",
        "`cncc port` writes a called subprogram in the target's own form: for Heidenhain `CALL LBL n` with the subprogram as `LBL n` ... `LBL 0` after the main program's end (a repeat count becomes a program-section repeat around the call); from Heidenhain a label subprogram becomes the target's local subprogram. The called program must be found beside the program (`O1000.nc` for `M98 P1000`), be ported itself, and its number and repeat count must be known numbers. Give the count as a number, put the subprogram file beside the program, or expand the call in the source.";
    PortQParameter = "E0621", "port-q-parameter", Error,
        "a variable with no Heidenhain Q parameter, or a Q parameter with no variable in the target",
        "Porting to Klartext, numbered variables take fixed Q numbers (`#0..#99` and `R0..R99` to `Q0..Q99`, `#100..#499` and `R100..R499` to `Q1600..Q1999`, the user ranges) and named or declared variables take local `QL` parameters. Porting from Klartext, `Q0..Q99` and `Q1600..Q1999` go back to those numbers and `QL` parameters to free variables of the target. Other numbers (Fanuc `#500` up, the control's own `Q100..Q199`), indirect and system variables and arrays have no counterpart: renumber them in the source.";
    PortJump = "E0622", "port-jump", Error,
        "a condition or jump that has no form in the target",
        "Porting to Klartext, loops and conditionals become labels and the conditional jumps `FN 9..12` (EQU, NE, GT, LT; the others as two jumps), combined with AND, OR and NOT. A condition of another kind (bitwise operators, a computed jump target, CASE) has no such form. Porting from Klartext to a target without jumps (LinuxCNC), a backward conditional jump becomes a `do`/`while` loop and a forward one an `if` block only when the jumps nest like loops and conditionals do; rewrite the others.";
    PortTncFormula = "E0623", "port-tnc-formula", Error,
        "a function or expression Klartext formulas have no counterpart for",
        "A Klartext Q parameter formula has + - * / ^ and SIN COS TAN ASIN ACOS ATAN SQRT SQ ABS INT LN EXP; the angle of two values is `FN 13`, an assignment of its own. `cncc port` writes POW as `^`, an ATAN of two values that is a whole assignment as FN 13, and the rounding functions (ROUND, FIX, FUP, floor, ceiling) exactly with INT and SGN; MIN, MAX, BIN, BCD and an ATAN of two values inside a larger formula have no counterpart. Rewrite them in the source.";
    PortApproximate = "W0610", "port-approximate", Warning,
        "a construct carried to the target with a documented difference",
        "The target's form of this construct does the same cutting but differs in something the port cannot make equal (a spindle orientation, a register the target derives itself, a re-entry distance). Read the message; `--verify` shows whether the cutting moves still match.";
    PortExpanded = "W0612", "port-expanded", Warning,
        "a part of the program written as the moves it makes",
        "The target has no form for a construct here (a cycle, a subprogram, a loop, a function), so `cncc port` ran the program and wrote the smallest part around it that starts and ends in a plain modal state as the moves, arcs, feeds, speeds, tool changes and coolant it makes, in absolute coordinates, followed by the modes and variables it leaves. The cut is the same (the port verifies it), but the target's program no longer shows the construct. `--strict` refuses instead; rewrite the construct by hand if the target's own idiom is wanted.";
    PortDeadSubprogram = "W0613", "port-dead-subprogram", Warning,
        "a subprogram the program never calls, carried as comments",
        "The target has no form for something in a subprogram that this program never calls (a Heidenhain `LBL` after the program's end that no `CALL LBL` reaches, a LinuxCNC `o<name> sub` of the main file that no `call` reaches). Such a subprogram can only be called from its own program, so it never runs: `cncc port` writes its text as comments in the target, after the rest, so nothing is lost and nothing of it can run. The run must reach the program's end for this (a run that stops on an unknown value cannot show that the subprogram is never called). A numbered program of its own in the file (Fanuc `O2000`) may be called by other programs and is never treated so. Port it by hand, or delete it in the source, if the text is not wanted.";
    RateRounded = "W0614", "rate-rounded", Warning,
        "a feed or spindle speed rounded to the target's decimal places",
        "The target writes feeds and speeds with fewer decimal places than the value has (a computed feed such as 33.333333, a CAM feed of 18.7734 for a control that writes three places). When rounding changes the value by less than 0.02 % (cncc's rate tolerance, the one `--verify` compares feeds and speeds with), it is written rounded and reported here: no machine resolves a feed that finely. A larger change is refused (E0603).";
    VerifyRapids = "W0611", "verify-rapids-differ", Warning,
        "the ported program's rapid moves differ from the source's",
        "`--verify` found the same cutting moves, but some rapid (G0) moves go elsewhere above the highest cutting height, or in the approach after a tool change (for example a cycle that returns to another clearance level). They do not cut, but check them for collisions. A differing rapid below the cutting height is an error (E0616).";
    LengthWithoutPoint = "W0001", "length-without-decimal-point", Warning,
        "a length written without a decimal point",
        "With the decimal-point rule of this dialect (Fanuc parameter 3401#0 = 0), `X10` means 10 least input increments (0.010 mm or 0.0010 in), not 10 mm. Write `X10.` if whole units are meant. Load a spec with `integer-lengths=\"units\"` for a control set to calculator-type input.";
    DialectDetected = "W0002", "dialect-detected", Note,
        "the dialect was chosen from the file's name or content",
        "Without `--dialect`, cncc chooses the dialect from the file extension and its content. Give `--dialect` to be sure.";
    UnknownSubprogram = "W0003", "unknown-subprogram", Warning,
        "a call to a subprogram not found in this file",
        "The called subprogram is not defined in this file. It may live in another file on the controller; cncc cannot check its arguments.";
    SuspectWord = "W0004", "suspect-word", Warning,
        "a word that has no effect here",
        "The word is read but nothing in this block uses it.";
    BadToolTable = "E0502", "bad-tool-table", Warning,
        "a tool table line that cannot be read",
        "Tool table lines are `T<tool> P<pocket> Z<length> D<diameter> ;comment` (LinuxCNC's .tbl format). The line was skipped.";
    KeptAsText = "W0005", "kept-as-text", Warning,
        "a block understood only as text",
        "The front end recognised the block as plausibly valid for the dialect (an unknown system function, an unusual keyword) but cannot place it in the meta-model. It is kept verbatim: it is written back unchanged into the same dialect, and translating it to another dialect is an error.";
    CrLineEnds = "W0006", "cr-line-ends", Note,
        "lines that end with a lone carriage return",
        "The file ends its lines with CR alone (classic Mac OS, some DNC software), not LF or CR LF. cncc reads each CR as a line end; a controller or DNC link set for LF may read the whole file as one block. Convert the line ends if the machine needs it.";
    AfterClosingPercent = "W0007", "after-closing-percent", Note,
        "text after the closing % that is not read",
        "In this dialect the useful contents of a file stop at the second `%` line (LinuxCNC); everything after it is ignored, as the controller ignores it. Move what should run before the closing `%`.";
    DivisionByZero = "E0503", "division-by-zero", Error,
        "a division by zero while the program runs",
        "An expression divides by zero (or takes MOD of zero) with the values the variables have at that point. Check the divisor's variables.";
    UndefinedVariable = "E0504", "undefined-variable", Error,
        "a variable read before it was given a value",
        "The program reads a named parameter or variable that was never set (LinuxCNC: `Named parameter #<x> not defined`). Set it first, or check its spelling.";
    DomainError = "E0505", "domain-error", Error,
        "a function given a value outside its domain",
        "SQRT of a negative number, LN of zero or less, ASIN/ACOS outside -1..1: the controller alarms here. Check the argument's variables.";
    LimitExceeded = "E0506", "limit-exceeded", Error,
        "a loop, jump or call nesting ran past its limit",
        "cncc bounds loops, backward jumps and call nesting so that no program can hang it. The limit was reached: the program probably loops forever. Raise the limit with `--max-loop` / `--max-depth` if the program is right.";
    NoFeedRate = "E0507", "no-feed-rate", Error,
        "a feed move with no feed rate",
        "A G1/G2/G3 or cycle feed move runs with feed rate zero (none programmed yet, or G93 without F in the block). Program an F word.";
    ArcEndNotOnCircle = "E0508", "arc-end-not-on-circle", Error,
        "an arc whose end point is not on its circle",
        "The distances from the centre to the start and to the end differ by more than the tolerance. Check the centre words (I J K are incremental from the start unless G90.1) and the end point.";
    ArcRadiusTooSmall = "E0509", "arc-radius-too-small", Error,
        "an arc radius too small to reach the end point",
        "With the R form, the chord from start to end is longer than the diameter. Use a larger R, or check the end point.";
    UnsupportedHere = "E0510", "not-supported-here", Error,
        "a construct the interpreter cannot run",
        "The statement is read and kept, but cncc cannot run it (yet), so the canonical output would be wrong from here on. The run stops with this diagnostic.";
    RunStoppedEarly = "W0511", "run-stopped-early", Warning,
        "the run-time checks stop at a statement cncc cannot run",
        "`check` runs the program to find run-time mistakes. This statement is read and kept, but cncc cannot run it yet, so the blocks after it were not checked at run time. The program itself may be right.";
    ValueFromOutside = "W0590", "value-from-outside", Warning,
        "the run stops at a value the program gets from its caller or the machine",
        "This file is a subprogram, macro, PROC or library of subroutines: it gets its parameters from the program that calls it (Fanuc G65 arguments #1-#33, LinuxCNC sub parameters #1-#30, Siemens PROC parameters and R parameters, Heidenhain Q parameters) or from the machine (GUD variables). Checked alone, cncc cannot know those values, so the run-time checks stop where the first one is needed; every block was still checked for syntax and structure. Check the caller together with it (put both files in one folder and check the caller) to run it with real values.";
    CalledProgramMissing = "W0591", "called-program-missing", Warning,
        "a call to a program that is neither in this file nor beside it",
        "The program calls a subprogram or macro that cncc cannot find in the file or in the same folder (as `O1000.nc`, `L54.SPF`, `name.ngc`...). The controller may well hold it (a machine builder's macro, a program kept in the control's memory), so the call is not an error, but what it does was not checked: the run goes on after the call as if it had returned without moving. Put the called program beside this one to check it too.";
    ToolSizesInvented = "W0592", "tool-sizes-unknown", Warning,
        "tools whose sizes no tool table gave",
        "No tool table (`--tool-table`) gave these tools' lengths and diameters. Tools 1 to 20 got sizes from cncc's built-in table, which are invented (small inch end mills and drills); other tools, which the control holds in its own offset memory, run with no length and no diameter. Length offsets, radius compensation and anything measured with the tool were checked with those sizes, not the shop's. Give the shop's tool table to check them for real.";
    BadParameterFile = "E0593", "bad-parameter-file", Error,
        "a parameter file LinuxCNC's interpreter does not start with",
        "A LinuxCNC parameter file (`.var`, `--var-file` or `[RS274NGC]PARAMETER_FILE`) gives one parameter a line, `NUMBER VALUE`, the numbers from 1 to 5601 in ascending order, each once. rs274 stops before the program with \"Parameter number out of range\" or \"Parameter file out of order\", so cncc does not run the program either. Correct or sort the line.";
    ParameterLineSkipped = "W0593", "parameter-line-skipped", Warning,
        "a parameter file line that is not `NUMBER VALUE`",
        "rs274 reads a parameter file line only when its first two words are an integer and a number; it skips any other line without a word, and so does cncc. The parameter the line meant to set keeps its value (0 for a persistent one). When rs274 writes the file back at the end of the run the line is gone.";
    BadIniLine = "W0594", "bad-ini-line", Warning,
        "an INI file line that is neither a section, a value nor a comment",
        "A LinuxCNC INI file holds `[SECTION]` lines, `NAME = VALUE` lines, and comment lines starting with `#` or `;`. LinuxCNC skips any other line, and so does cncc. A `\\` at the end of a line continues it on the next one.";
    BadIniSetting = "W0595", "bad-ini-setting", Warning,
        "an `[RS274NGC]` setting whose value the interpreter does not take",
        "The interpreter reads `ORIENT_OFFSET` as a number and `INI_VARS`, `DISABLE_G92_PERSISTENCE` and `DISABLE_FANUC_STYLE_SUB` as integers (0 off, anything else on); `SUBROUTINE_PATH` is a `:`-separated list of existing folders. A value it cannot read leaves the default (for `yes` or `true` too: write 1), a folder that does not exist is left out. The run goes on with the default; correct the value.";
    IniSettingNotApplied = "W0596", "ini-setting-not-applied", Warning,
        "an `[RS274NGC]` setting that cncc does not apply",
        "cncc applies these `[RS274NGC]` settings of a LinuxCNC INI file: SUBROUTINE_PATH, PARAMETER_FILE, INI_VARS, ORIENT_OFFSET, DISABLE_G92_PERSISTENCE and DISABLE_FANUC_STYLE_SUB. Remaps (REMAP), the FEATURES bits other than INI_VARS (4) and their switches (RETAIN_G43, OWORD_NARGS, NO_DOWNCASE_OWORD, OWORD_WARN_ONLY, HAL_PIN_VARS), ON_ABORT_COMMAND, RS274NGC_STARTUP_CODE, USER_M_PATH and the arc tolerances are not applied: the run goes on as if the setting were absent, so its calls may differ from LinuxCNC's where the setting matters.";
    RepeatedCode = "W0598", "repeated-code", Warning,
        "the same code written twice in one block",
        "The block gives one G or M code twice (`G0 G90 G0 X0`). On this control a code of a group written again replaces the first, so the block reads as if the code were written once, and it runs so. Remove the second one: a control that refuses two codes of one group (LinuxCNC) stops on it.\n\nBad:\n    G0 G90 G0 X0 Y0\n\nGood:\n    G0 G90 X0 Y0";
    ArcWordsWithoutArc = "W0597", "arc-words-without-arc", Warning,
        "centre or radius words in a block that moves straight",
        "The block has no motion code of its own and the modal motion is G0 or G1, so it moves in a straight line: its centre (I J K) or radius (R) words belong to no arc and are not used. Usually a G2/G3 was lost, or the words were meant for something else (arguments written after an M98 subprogram call, which passes none; G65 passes them). The run goes on with the straight move; write the arc's G2/G3, or remove the words.\n\nBad:\n    G1 X10. Y0. F100.\n    X0. Y10. I-10. J0.\n\nGood:\n    G1 X10. Y0. F100.\n    G3 X0. Y10. I-10. J0.";
    ProgramAborted = "E0595", "program-aborted", Error,
        "the program stopped itself with an (ABORT, text) comment",
        "LinuxCNC's `(ABORT, text)` comment stops the run with its text as the error, parameters substituted as in `(DEBUG, ...)`. The program's own check failed here; the text says why.";
    SubStyleDisabled = "E0594", "sub-style-disabled", Error,
        "an M98 call where the configuration disables Fanuc-style subprograms",
        "The INI file sets `[RS274NGC]DISABLE_FANUC_STYLE_SUB`, so LinuxCNC refuses M98 (and the `O1 ... M99` programs it calls). Call an `o1 sub ... o1 endsub` with `o1 call`, or drop the setting.";
    NamedToolWithoutTable = "W0516", "named-tool-without-table", Warning,
        "a tool called by name with no tool table to find it in",
        "Siemens tool management calls tools by name (`T=\"FACEMILL 63\"`). cncc finds a named tool by the comment of a row of the tool table given with `--tool-table`; without one, only the built-in tools T1..T20 exist. The run goes on with a tool of no length and no diameter under that name, so lengths and radius compensation are not checked for it: give a tool table whose row carries the name as its comment.";
    CannotExpandCycle = "W0510", "cycle-not-expanded", Warning,
        "a cycle the interpreter cannot expand into moves",
        "The cycle is kept in the program, but its documentation does not define its toolpath well enough for cncc to generate it; the canonical output skips its moves.";
    KeptAsToolpathFeature = "W0870", "kept-as-toolpath-feature", Warning,
        "moves left as a toolpath feature when raising to STEP-NC features",
        "`cncc stepnc --cc2` recognises drilled holes, faces, pockets, slots, steps and outside profiles in the moves. These moves matched none of them (or the tool's diameter is not known), so they are carried as a TOOLPATH_FEATURE with a FREEFORM_OPERATION holding the explicit toolpath: nothing is lost, but the feature is not described. Give the tool table and stock, or program the feature in a recognisable way.";
    BlankNotRead = "W0580", "blank-not-read", Warning,
        "a BLK FORM blank that cannot be taken as the stock",
        "Without `--stock`, `cncc stepnc` takes the workpiece's raw stock from the program's Heidenhain `BLK FORM 0.1` (minimum point) and `BLK FORM 0.2` (maximum point, absolute or incremental from the minimum). These blocks were incomplete, used parameters, or gave no volume, so the project has no raw piece. Give both points with numbers for X, Y and Z, or give `--stock`.";
    CancelOverridden = "W0581", "cancel-overridden", Warning,
        "a G80 beside a motion code of its modal group",
        "LinuxCNC accepts G80 in a block with another motion code (`G80 G0 X0 Y0`): the motion code sets the motion mode and the G80 counts for nothing. cncc reads the block the same way and notes it; remove the G80, or put it in a block of its own to cancel a cycle before the move.";
    CycleRBelowBottom = "E0540", "cycle-r-below-bottom", Error,
        "a canned cycle whose R plane is below its bottom",
        "In LinuxCNC (capability `cycle-r-above-bottom`) the retract (R) plane of a drilling cycle must not be below the hole bottom along the drilling axis; Fanuc and Haas drill from R towards the bottom whichever way that is (a right-angle head drilling up the Y axis). Check the signs of R and Z (in G91, R is measured from the initial level and Z from R). Fanuc back boring (G87, Haas G77) is the other way round (R below Z, W0521).";
    CycleMissingWord = "E0541", "cycle-missing-word", Error,
        "a canned cycle without a word it needs",
        "The first block of a canned cycle must give the bottom (Z, or the drilling axis of the plane) and R; G82/G86/G88/G89 need P, G73/G83 need Q, LinuxCNC's G87 needs I, J and K (Fanuc's G76/G87 shift by the retained Q instead). Later blocks of the same cycle may leave them out: the values stay in force.";
    CycleBadPeck = "E0542", "cycle-bad-peck", Error,
        "a peck depth Q that is zero or negative",
        "G73 and G83 drill in steps of Q, which must be greater than zero.";
    CycleBadRepeat = "E0543", "cycle-bad-repeat", Error,
        "a canned-cycle repeat count (L or K) that is zero, negative or not whole",
        "L (or K) gives how often the cycle runs. LinuxCNC rejects zero and negative counts; Fanuc's K0 only stores the cycle data.";
    CycleSpindleState = "E0544", "cycle-spindle-state", Error,
        "a tapping or boring cycle with the spindle stopped or turning the wrong way",
        "G84 needs the spindle turning clockwise (M3), G74 counterclockwise (M4); G86, G87, G88 and G76 need it turning. Start the spindle before the cycle.";
    CycleBadArgument = "E0545", "cycle-bad-argument", Error,
        "a named cycle or hole pattern with a missing or impossible argument",
        "A Siemens drilling cycle needs RTP and RFP and a depth (DP or DPR); the reference plane must lie above the depth. Hole patterns need a positive whole number of holes.";
    BoreNoShift = "W0520", "bore-no-shift", Warning,
        "an oriented boring cycle that shifts by nothing",
        "Fanuc and Haas fine boring (G76) and back boring (Fanuc G87, Haas G77) stop the spindle oriented and shift the tool by Q away from its tip, so that the edge leaves the wall. Q is the canned cycles' retained value (also the G73/G83 peck depth): a block without Q uses the last Q, which is 0 at power-on. With no shift the control still runs the cycle, but the edge drags up the finished bore (G76) or meets the part on the way down (back boring). Give Q (a positive distance) in the cycle block; the direction is a machine setting (Fanuc parameter 5101, Haas setting 27), `shift` in the dialect spec.";
    BackBoreDownward = "W0521", "back-bore-downward", Warning,
        "a back boring cycle whose R is above its Z",
        "In Fanuc back boring (G87; Haas G77) R is the level below the part where the oriented, shifted tool enters, and Z the top of the bore it then cuts upwards, so R lies below Z. With R above Z the control still runs the cycle as written [?: no alarm is documented]: down to R, then a feed down to Z, which is a plain boring pass, not a back bore. Posts that write G87 with the R and Z of their other cycles make this; give R below the part and Z at the top of the counterbore.";
    CycleZeroFeed = "E0546", "cycle-zero-feed", Error,
        "a canned cycle with no feed rate",
        "Drilling cycles feed into the material at the active feed rate, which is zero here. Program F before or in the cycle block.";
    ToolNotInTable = "E0501", "tool-not-in-table", Error,
        "a tool that is not in the tool table",
        "The program selects or changes to a tool number that the tool table does not list. Add the tool to the table given with `--tool-table`, or correct the number.";
    CompGouge = "E0550", "comp-gouge", Error,
        "a concave corner that the compensated tool cannot reach without gouging",
        "With cutter radius compensation on, the tool would have to back up along a move (or sweep further round an arc) to fit into an inside corner, so it would cut into the part. Use a smaller tool, or make the inside corner or the short move larger than the tool radius.";
    CompArcTooSmall = "E0551", "comp-arc-too-small", Error,
        "the tool radius is not less than the radius of an arc it cuts inside",
        "With the tool on the inside of an arc, the compensated arc has radius arc radius minus tool radius, which must be positive. Use a smaller tool or a larger arc.";
    CompEntryTooShort = "E0552", "comp-entry-too-short", Error,
        "the entry move after G41/G42 is not longer than the tool radius",
        "The first move after turning compensation on must end more than one tool radius from where it starts, so that the tool can be put beside the programmed end point. Start farther away.";
    CompNotXyPlane = "E0553", "comp-not-xy-plane", Error,
        "cutter radius compensation outside the XY plane",
        "cncc computes cutter radius compensation in the XY plane (G17) only, as LinuxCNC does for mills. Select G17 before G41/G42.";
    CompStateChange = "E0554", "comp-state-change", Error,
        "a change that is not allowed while cutter radius compensation is on",
        "Turning compensation on while it is on, or changing plane, needs G40 first.";
    KlartextEndNameMismatch = "W0120", "klartext-end-name", Warning,
        "END PGM names another program than BEGIN PGM",
        "A Klartext program begins with `BEGIN PGM name unit` and ends with `END PGM name unit`, the same name in both; the TNC writes them so. A different name at the end is usually a program copied under a new name (or a post's mistake). The program still ends there; correct the name.";
    KlartextUnknownBlock = "E0120", "klartext-unknown-block", Error,
        "a Klartext block that does not start with a known function",
        "A Heidenhain block starts with its path or program function: L, C, CC, CR, CT, LP, CP, CTP, RND, CHF, APPR, DEP, LBL, CALL, FN, CYCL DEF, CYCL CALL, TOOL DEF, TOOL CALL, BLK FORM, PATTERN DEF, STOP, a Q parameter formula, or M functions alone. Check the spelling (`CYCL`, not `CYCLE`).";
    KlartextAxisWithoutValue = "E0121", "klartext-axis-without-value", Error,
        "an axis word without a coordinate",
        "In a path block every axis word needs its coordinate: `X+10`, `IY-5`, `Z+Q3`. Give the value, or remove the letter.";
    KlartextWordNotAllowed = "E0122", "klartext-word-not-allowed", Error,
        "a word this Klartext block does not take",
        "Each Klartext function takes its own words (L: axes, R0/RL/RR, F/FMAX/FAUTO, M; C: axes, DR+/DR-; RND: R, F; ...). Remove the word or move it to a block that takes it.";
    KlartextMissingWord = "E0123", "klartext-missing-word", Error,
        "a Klartext block without a word it needs",
        "C, CR and CP need the direction DR+ or DR-; CR needs its radius R; RND needs R; APPR/DEP need their kind (LT, LN, CT, LCT). Add the word.";
    KlartextBadCycle = "E0124", "klartext-bad-cycle", Error,
        "a cycle definition that cannot be read",
        "`CYCL DEF` is followed by the cycle number (200, 251 ... or old-style 7.0, 7.1 ...) and, for the numbered cycles, one `Qnnn=value` per parameter. Check the number and the parameter lines.";
    KlartextContinuationAtEnd = "E0125", "klartext-continuation-at-end", Error,
        "a block continued with `~` at the end of the file",
        "A trailing `~` says the block goes on in the next line, but the file ends. Complete the block or remove the `~`.";
    KlartextBadFunction = "E0126", "klartext-bad-function", Error,
        "an FN 14..20 function block that cannot be read",
        "FN 14 is `FN 14: ERROR= n`; FN 15 `FN 15: PRINT` followed by Q parameters, numbers or quoted texts; FN 16 `FN 16: F-PRINT mask/output`; FN 18 `FN 18: SYSREAD Qn = IDg NRn IDXi` (IDX optional); FN 17/19/20 are `SYSWRITE`, `PLC`, `WAIT FOR`. Check the keyword after the colon and the words after it.";
    KlartextBadPlane = "E0127", "klartext-bad-plane", Error,
        "a PLANE block that cannot be read",
        "A PLANE block names how the plane is defined (RESET, SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, AXIAL), then its angles or vector components (`SPA+0 SPB+45 SPC+0`) and how the rotary axes go (MOVE, TURN, STAY), with optional MB, FMAX, F, DIST, SEQ, TABLE ROT/COORD ROT. Check the words.";
    KlartextBadParaxial = "E0128", "klartext-bad-paraxial", Error,
        "a paraxial R+/R- block with other than one axis",
        "`L X+10 R+` moves along one axis with the path lengthened (R+) or shortened (R-) by the tool radius. It takes exactly one axis word of the working plane and no RL/RR. Split the move, or use RL/RR radius compensation.";
    KlartextCycleMissingParameter = "E0320", "cycle-missing-parameter", Error,
        "a Heidenhain cycle without a Q parameter it needs",
        "Each numbered cycle needs its parameters (for 200 DRILLING: Q200 set-up clearance, Q201 depth, Q206 feed, Q202 plunging depth, Q203 surface, Q204 2nd set-up clearance ...). Add the missing `Qnnn=value` line to the CYCL DEF.";
    KlartextLabelMissing = "E0321", "label-missing", Error,
        "a CALL LBL or GOTO LBL to a label the program does not have",
        "`CALL LBL n`, `CALL LBL n REP m` and `FN 9..12: ... GOTO LBL n` need a block `LBL n` (or `LBL \"name\"`) in the same program. Add the label or correct the number.";
    KlartextNoCentre = "E0560", "circle-without-centre", Error,
        "a circular block with no circle centre (CC) before it",
        "C and CP blocks turn around the pole set by CC; polar LP/CTP blocks measure from it. Program `CC X.. Y..` before the first such block.";
    KlartextCornerCannotFit = "E0561", "corner-cannot-fit", Error,
        "RND or CHF between elements that cannot take it",
        "A rounding (RND) or chamfer (CHF) joins two path elements in the working plane. It needs a path element before and after it, and must be small enough to fit on both; a chamfer joins two straight lines. Reduce the size or move the block.";
    KlartextTangentUndefined = "E0562", "tangent-undefined", Error,
        "a tangential element with no direction to be tangent to",
        "CT, CTP and APPR/DEP need a path element before them (in the working plane) whose direction they continue. Program a straight line or an arc first.";
    KlartextProgramError = "E0519", "program-raised-error", Error,
        "the program stopped itself with FN 14: ERROR",
        "`FN 14: ERROR= n` stops the program run with the control's error number n (the program's own check failed: an input parameter out of range, a missing tool ...). The run stops here as the control's would. Read the program's comments near the block for what the number means, and correct the input it checks.";
    KlartextUnknownSystemDatum = "E0520", "unknown-system-datum", Error,
        "FN 18: SYSREAD of a system datum the run does not know",
        "The run knows these FN 18 data (numbers from the TNC system data table, values in mm): ID10 NR1 (program unit, 0 mm / 1 inch) and NR3 (active cycle), ID20 NR1 (active tool), NR3 (tool axis, 0 X 1 Y 2 Z), NR4 (spindle speed) and NR9 (feed), ID50 NR1/NR2 IDXt (length/radius of tool t in the table), ID60 NR1 (tool called), NR4/NR5 (its DL/DR), ID200 NR1/NR2 (active radius/length with the oversizes), ID270 NR1 IDX1..9 (position in the active coordinate system). Any other datum depends on the machine. (This error is no longer raised: such a datum is now unknown at check time, W0517, and the run goes on.)";
    TiltNeedsRotaryAxes = "E0521", "tilt-needs-rotary-axes", Error,
        "a tilted working plane on a 3-axis run",
        "PLANE SPATIAL/PROJECTED/EULER/VECTOR/POINTS/RELATIV/AXIAL with a non-zero tilt turns the working plane with the machine's rotary axes (or the tilting head). cncc runs programs on a 3-axis machine, as LinuxCNC's canonical calls describe it, so the tilt cannot be made. PLANE RESET and a zero tilt run. Machine the feature in the untilted plane or run the program on a 5-axis control.";
    FormattedPrintNotRead = "W0512", "formatted-print-not-read", Warning,
        "FN 16: F-PRINT whose mask file is not read",
        "FN 16 writes Q parameter values formatted by a mask file on the control. cncc does not read the mask: the run shows a MESSAGE naming the mask and the output and goes on.";
    MachineFunctionNotRun = "W0513", "machine-function-not-run", Warning,
        "an FN function that talks to the machine (PLC, SYSWRITE, WAIT FOR) is not run",
        "FN 17 SYSWRITE, FN 19 PLC and FN 20 WAIT FOR act on the machine's own data, PLC or synchronisation, which a canonical run does not have. The block is reported and skipped; the run goes on. Check what the program expects of it.";
    UnknownAtCheckTime = "W0517", "unknown-at-check-time", Note,
        "a value the run cannot know at check time",
        "Some values exist only on the machine: FN 18 system data such as the position in the machine (REF) system (ID240), which depends on where the preset lies, or the end of travel that `M140 MB MAX` retracts to. The run goes on with the value unknown: parameters read from it stay unknown (formulas of them too) and are never reported as errors; moves to an unknown coordinate are not checked. Give the value with a machine description where cncc can read one.";
    MachineFunctionAssumed = "W0519", "machine-function-assumed", Warning,
        "an M code the dialect does not know, run as a machine function that does not move the axes",
        "The machine builder's own M codes (a clamp, a chip conveyor, a probe switch, an air blast) are not in the dialect's table, so cncc cannot know what they do. The run goes on as if the code switches something without moving the axes and without changing any modal state the run computes; positions after it are the programmed ones. If the code moves the machine (a tool-change or pallet macro) or changes a mode, describe it in a dialect file (`--dialect-file`, `<code letter=\"M\" ...>` with its meaning or `run=`), so that the run knows. A port carries the code as it is written, so source and target make the same assumption. Reported once per run, at the first such code (each code is also reported where it is written, E0204).";
    KinematicsNotRun = "W0518", "kinematics-not-run", Warning,
        "a tilted plane or tool-centre-point function that the 3-axis run does not make",
        "PLANE SPATIAL/PROJECTED/EULER/VECTOR/POINTS/RELATIV/AXIAL with a non-zero tilt, cycle 19, FUNCTION TCPM and M128 turn the working plane or keep the tool tip on the path while rotary axes move. They need the machine's kinematics, which a canonical 3-axis run does not have. The program is read and kept as written (a port to Klartext writes it back); the run goes on in the untilted plane with the coordinates as programmed, so the positions it shows after this block differ from the machine's. Reported once per run.";
    CompExitArc = "E0555", "comp-exit-arc", Error,
        "an arc as the first move after G40",
        "The move after cancelling compensation with G40 takes the tool off the compensated path and must be a straight line.";
    BadWordValue = "E0511", "bad-word-value", Error,
        "a word missing or with a value the controller rejects when the block runs",
        "The block needs a word it lacks (G4 without P, G10 without P) or has one whose value is out of range (a negative F or S, G10 L2 P10, axis words with G80). The controller alarms here.";
    RaiseCommentsNotCarried = "W0860", "raise-comments-not-carried", Warning,
        "comments that STEP-NC has no place for",
        "ISO 14649 has no comment entity. When a program is raised to STEP-NC, a comment just before a cut names the workingstep that follows; the other comments are not carried. The warning points at the first one and counts them.";
    RaiseToolWithoutDiameter = "W0861", "raise-tool-without-diameter", Warning,
        "a tool the tool table does not give a diameter for",
        "STEP-NC tools carry their geometry, and raised holes take their diameter from the drill. The tool is written with diameter 0. Give a tool table (`--tool-table T.tbl`, LinuxCNC format) that lists the tool with its D word.";
    RaiseHelixAsPolyline = "W0862", "raise-helix-as-polyline", Warning,
        "helical moves written as polylines",
        "The STEP-NC model cncc writes has circles but no helices, so a helical move (an arc whose axis coordinate changes) is written as a cutter-location polyline within 0.001 mm of the true path. The warning points at the first one and counts them.";
    RaiseCycleAsToolpath = "W0863", "raise-cycle-as-toolpath", Warning,
        "a canned cycle kept as explicit toolpaths, not as a hole",
        "Drilling, peck drilling, boring and reaming cycles become ROUND_HOLE features with their operation. A cycle whose moves match none of them (tapping, back boring, a cycle that is not vertical) is kept as the explicit toolpath of a freeform operation, so nothing is lost, but it is not a hole feature.";
    RaiseTableLooksMetric = "W0864", "tool-table-units", Warning,
        "a tool table read in inches whose sizes look like millimetres",
        "LinuxCNC tool tables carry no units: their numbers are in machine units, inches unless `--machine-units mm` is given (as in LinuxCNC's standalone interpreter). Read in inches, a tool in this table is over 300 mm across, which is more likely a metric table. Pass `--machine-units mm` if its numbers are millimetres.";
    ArcBadWords = "E0512", "arc-bad-words", Error,
        "an arc without a centre or radius, or with both",
        "G2/G3 need either the centre words (I J K for the active plane) or R, not both and not neither. A full circle needs the centre words.";
    // ---- E08xx / W08xx: STEP-NC Part 21 files (src/stepnc)
    P21Syntax = "E0800", "p21-syntax-error", Error,
        "a Part 21 statement that does not follow ISO 10303-21",
        "A STEP file is made of `#n=ENTITY(parameters);` instances between `DATA;` and `ENDSEC;`. Parameters are separated by commas: strings in single quotes, reals with a decimal point, enumerations between dots, `$` for an unset value, `#n` for a reference and lists in parentheses. The message names what was found and what could come instead; the instance is skipped.";
    P21UnreadableText = "E0801", "p21-unreadable-text", Error,
        "text in a Part 21 file that starts no token (or a string or comment that never closes)",
        "A Part 21 file contains only names, numbers, strings in single quotes, enumerations like `.T.`, `#n` references, the punctuation `( ) , = ; $ *` and comments `/* ... */`. Close the string with `'` (write `''` for a quote inside it) or the comment with `*/`, or remove the character.";
    DanglingReference = "E0802", "dangling-reference", Error,
        "a `#n` reference to an instance the file does not contain",
        "Every `#n` used as a parameter must be defined somewhere in the DATA section as `#n=...;`. Define the instance or correct the number.";
    WrongArgumentCount = "E0803", "wrong-argument-count", Error,
        "an instance with more or fewer parameters than its entity has attributes",
        "A Part 21 instance lists every attribute of its entity, supertype attributes first, in the order of the EXPRESS schema; unset optional attributes are written `$`. `cncc explain` cannot show the schema, but `cncc query FILE.stp /#n` prints the attribute names cncc expects.";
    WrongArgumentType = "E0804", "wrong-argument-type", Error,
        "a parameter of the wrong kind (a string where a number belongs, `$` for a mandatory attribute...)",
        "Each attribute has a type in the ISO 14649 schema: measures are reals, identifiers strings, booleans `.T.`/`.F.`, aggregates lists `(...)` (an empty one is `()`, never `$`) and entities `#n` references to an instance of a fitting entity. Only OPTIONAL attributes may be `$`.";
    UnknownEntity = "E0805", "unknown-entity", Error,
        "an entity name that is not in the ISO 14649 schema cncc knows",
        "cncc reads the ISO 14649-10, -11 and -111 entities (and the ISO 10303-42 geometry they use), with the spelling variants real files use (`BIDIRECTIONAL_MILLING`, `TOOL_DIMENSION`, `CENTER_DRILL`, `ELEMENTARY_SURFACE`). Check the spelling; an entity of another schema cannot be read.";
    UnsupportedSchema = "E0806", "unsupported-schema", Error,
        "a STEP file of a schema cncc does not read (such as the AP238 ed.2 AIM)",
        "cncc reads ISO 14649 ARM files, whose FILE_SCHEMA is ('MACHINING_SCHEMA','MILLING_SCHEMA') or ('COMBINED_SCHEMA'), and the explicit toolpaths of AP238 ed.1 AIM files (INTEGRATED_CNC_SCHEMA, see W0807). AP238 ed.2+ files (MODEL_BASED_INTEGRATED_MANUFACTURING_SCHEMA) and other schemas are not read. Export the ARM form from the CAM system.";
    StepncModel = "E0807", "stepnc-model-error", Error,
        "a STEP-NC file whose instances do not make an ISO 14649 project",
        "The file parses, but an attribute refers to an instance of the wrong kind (an operation where a feature belongs...), or there is no PROJECT. The message names the attribute and what it expected.";
    DuplicateInstance = "E0808", "duplicate-instance-number", Error,
        "two instances with the same `#n`",
        "Instance numbers are unique within a file; references to the number would be ambiguous. The first instance is kept; renumber the second.";
    ComplexInstance = "E0809", "complex-instance", Error,
        "a complex instance `#n=(A(..)B(..))` where ISO 14649 expects a simple one",
        "ISO 14649 ARM files use only simple instances; complex ones belong to AIM files (units). The instance is read but cannot become part of the model.";
    BadQueryPath = "E0810", "bad-query-path", Error,
        "a `cncc query` path that names no attribute or index of the file",
        "A path starts at an entity (`/project`) or an instance (`/#18`) and goes on through attribute names (`/its_id`), indexes (`[0]`) and `[*]` for every element of a list. The message names the step that failed and the attributes there.";
    P21Structure = "E0811", "p21-file-structure", Error,
        "a Part 21 file without its ISO-10303-21 / HEADER / DATA / ENDSEC structure",
        "A Part 21 file starts with `ISO-10303-21;`, has a `HEADER;` section (FILE_DESCRIPTION, FILE_NAME, FILE_SCHEMA) and a `DATA;` section each closed by `ENDSEC;`, and ends with `END-ISO-10303-21;`.";
    P21TooDeep = "E0812", "p21-too-deep", Error,
        "instances that refer to each other too deeply (or in a cycle) to be read",
        "Following references from the project reached more than 200 levels, or came back to an instance it was still reading. ISO 14649 data is a tree of shallow depth; check the references named.";
    DuplicateItsId = "W0800", "duplicate-its-id", Warning,
        "two features, operations or executables with the same its_id",
        "ISO 14649 asks the its_id of the project, executables, features and operations to be unique within the programme; real files break this. Both are kept, but queries and differences by id may be ambiguous.";
    UnusedInstance = "W0801", "unused-instance", Warning,
        "an instance the project never refers to",
        "The instance is not reachable from the PROJECT, so it is not part of the programme and a normalised file leaves it out. Remove it, or refer to it.";
    MandatoryUnset = "W0803", "mandatory-unset", Warning,
        "a mandatory attribute written `$`",
        "The schema does not make this attribute OPTIONAL, yet the file leaves it unset, as some generators do. cncc reads on and keeps the instance as written; other readers may refuse the file.";
    TappingWithoutPitch = "W0804", "tapping-without-pitch", Warning,
        "a TAPPING or THREAD_DRILLING operation whose thread pitch cannot be worked out",
        "ISO 14649 gives a tapping operation's thread pitch as its technology's feed over its spindle speed, the two synchronised (`synchronize_spindle_with_feed`). This operation lacks a feedrate or a spindle speed (or the speed is 0), or does not synchronise them, so the pitch is unknown or may not be kept. cncc reads on; posting it fails (E0906) until the technology gives both.";
    TapHandAgainstSpindle = "W0805", "tap-hand-against-spindle", Warning,
        "a tap whose hand_of_cut disagrees with the spindle direction of its operation",
        "A right-hand tap cuts turning clockwise (M3; ISO 14649 writes that speed negative), a left-hand tap counter-clockwise (M4; positive in the file). The TAP tool's hand_of_cut and the tapping operation's spindle speed disagree. cncc reads on; posting it fails (E0907) until they agree.";
    AbstractInstance = "W0806", "abstract-instance", Warning,
        "an abstract ISO 14649 entity instantiated",
        "The file instantiates an entity the schema declares ABSTRACT (JSDAI writers put `CUTTING_TOOL(id, body, edges, length)` where ISO 14649-111 asks for its subtype MILLING_CUTTING_TOOL). cncc reads it as that subtype, its added attributes unset, and writes the subtype back.";
    Ap238NotRead = "W0807", "ap238-not-read", Warning,
        "AP238 (integrated CNC schema) content cncc does not read: named, and left out of the plan",
        "cncc reads AP238 AIM files (FILE_SCHEMA INTEGRATED_CNC_SCHEMA) as far as their explicit toolpaths go: the workplan and its workingsteps, the tools and their body properties, technology (feed, spindle), machine functions (coolant) and cutter-location toolpaths (polylines, composite curves, trimmed lines and circles) with the units the file assigns. Feature geometry, strategies, B-splines and other properties are named in this warning and left out: the plan runs without them.";
    Ap238UnitsDoubtful = "W0808", "ap238-units-doubtful", Warning,
        "an AP238 feed and tool whose values, in the units the file declares, are implausible for milling",
        "cncc converts every AP238 value by the unit the file declares for it (a length by its LENGTH_MEASURE_WITH_UNIT or its representation context, a feed by its DERIVED_UNIT). Read so, this operation's feed or its tool's cutting speed (π·diameter·rpm) is beyond what milling runs (above 20 000 mm/min or 2 000 m/min [?]), while the same numbers read as millimetres would not be: the file may write millimetre values under an inch (or other) unit. cncc keeps the declared units; check the file's units with its author, or re-export it in the units its values are in.";
    KeptRaw = "W0802", "kept-raw", Warning,
        "a value cncc could not read into its model, kept as written",
        "The instance does not have the form ISO 14649 gives it (a mandatory attribute unset, an unexpected entity), so the typed model keeps it as written and carries it to the output unchanged, but it takes no part in checks, differences or posting.";
    NurbsAbandoned = "E0514", "nurbs-abandoned", Warning,
        "NURBS control points gathered by G5.2 that are never cut",
        "G5.2 blocks gather control points that G5.3 cuts as one curve. Another motion (or the program end) before G5.3 drops them: LinuxCNC cuts nothing and says nothing. End the G5.2 block with G5.3.";
    PolarAtOrigin = "E0513", "polar-at-origin", Error,
        "incremental polar words (@ ^) at the program origin",
        "Under G91 the polar words add to the current point's distance and angle from the program origin; at the origin that angle is undefined, so LinuxCNC rejects the move (or the canned-cycle repeat). Move off the origin first, or use G90 polar words.";
    CircularPocketComp = "E0515", "circular-pocket-comp", Error,
        "a Haas G12/G13 circular pocket with cutter compensation already on",
        "G12/G13 compensate their circles by the tool radius of their own D word. Cancel G41/G42 with G40 before the cycle, and give the offset with D (D0: the radii are the tool centre's).";
    CircularPocketRadius = "E0516", "circular-pocket-radius", Error,
        "a Haas G12/G13 circular pocket whose radii cannot be cut",
        "I (the first circle's radius) must be more than the radius of the tool D selects, and K (the finished radius), when given, must be more than I.";
    CircularPocketStep = "E0517", "circular-pocket-step", Error,
        "a Haas G12/G13 circular pocket with K but no positive Q",
        "With K the cycle cuts circles from I out to K, Q apart: Q must be given and greater than zero (less than the tool diameter to clear all the material).";
    TncCycleParameterMissing = "E0523", "cycle-parameter-missing-at-run", Error,
        "a Heidenhain cycle called without a Q parameter its run needs",
        "The cycle defined last lacks a Q parameter (E0320 names it where it is defined) and the run cannot go on without its value: the TNC asks for every parameter when the cycle is defined. Add the `Qnnn=value` line to the CYCL DEF.";
    TncCycleGeometry = "E0524", "cycle-geometry-impossible", Error,
        "a Heidenhain cycle whose sizes cannot be machined with the active tool",
        "The cycle's dimensions and the active tool do not fit: the tool is wider than the hole, slot or thread, a side is shorter than the stud it leaves, or a pitch or infeed is 0. The TNC stops with an error message here. Check the Q parameters and the tool radius (TOOL DEF or the tool table).";
    TncCycleNoToolRadius = "E0525", "cycle-without-tool-radius", Error,
        "a Heidenhain milling cycle run without a known tool radius",
        "Bore milling, thread milling, circular slots and studs place the tool centre from the tool radius. No radius is known for the active tool: program `TOOL DEF n L.. R..` or give a tool table with the tool's diameter.";
    TncCycleBadValue = "E0526", "cycle-parameter-out-of-range", Error,
        "a Heidenhain cycle parameter with a value the cycle does not accept",
        "A selector parameter has a value outside its list (Q214 disengaging direction 1 to 4, Q426 spindle direction 3, 4 or 5, Q367 position 0 to 4, Q215 0 to 2), or a count is not a positive whole number. Correct the value in the CYCL DEF.";
    TncCycleParameterNotApplied = "W0514", "cycle-parameter-not-applied", Warning,
        "a Heidenhain cycle parameter the simulated cycle does not apply",
        "The cycle runs, but the moves cncc generates for it do not take this parameter into account (a plunging strategy, an approach position, a finishing infeed): the parameter's effect on the real control is missing from the canonical output, plots and STEP-NC. The parameter is kept in the program and written back unchanged.";
    TncCycleMachineFunction = "W0515", "cycle-machine-function-not-run", Warning,
        "an M function given to a Heidenhain cycle that cncc does not simulate",
        "Cycle 241 switches coolant with the M functions in Q429/Q430. M7, M8 and M9 are run as mist, flood and coolant off; other numbers are machine-dependent (set by the machine builder), so they are not run and the canonical output lacks them.";
    EdgeNotInTable = "W0530", "edge-not-in-table", Warning,
        "a Siemens cutting edge D the tool table has no data for",
        "The tool table given to cncc (LinuxCNC's .tbl format) holds one cutting edge per tool. A Siemens program may select another edge (`D2`..) or, with flat D numbering (machine data 18102), any D number (`D08`): the control takes that edge's data from its own tool memory, which cncc cannot see. The run goes on with the tool's row of the table as the edge's length and radius, so length and radius checks after this block are only as good as that guess.";
    CornerFeedNotSimulated = "W0531", "corner-feed-not-simulated", Warning,
        "a corner feed override (Fanuc G62, Siemens G62/G621) is not simulated",
        "The control slows the feed at (inside) corners in this mode; the path itself does not change. cncc runs on with the path mode it had, so the canonical output, plots and time estimates keep the programmed feed at corners.";
    BlockTooLong = "E0191", "block-too-long", Error,
        "a block longer than cncc reads (1 MiB)",
        "A block, with all the lines continued into it, is longer than 1 MiB. No controller accepts such a block; it is not read, and the lines continued after the limit are not joined to it. Split it into several blocks.";
    ExpressionTooDeep = "E0190", "expression-too-deep", Error,
        "an expression nested deeper than cncc follows",
        "The expression nests more than 256 levels (brackets, functions or a chain of operators). Controllers allow far fewer (Fanuc: 5 levels of brackets). The block is not run. Split the expression into several assignments.";
    NotAFiniteNumber = "E0590", "not-a-finite-number", Error,
        "a calculation whose result is not a number or is infinite",
        "The value is undefined (a negative number to a fractional power, the square root of a negative number) or too large to hold (EXP[1000], 10**308*10). A controller stops with an alarm here; cncc stops the run at this block. Correct the calculation.";
    ValueOutOfRange = "E0690", "value-out-of-range", Error,
        "a value too large for the target's number format",
        "The target writes lengths, feeds and speeds with a limited number of digits (about 8 before the point): a larger value cannot be programmed and is not written. Check the units and the value in the source.";
    ActiveTextNeutralised = "W0690", "active-text-neutralised", Warning,
        "text that the target would read as a command, changed so it stays text",
        "A comment or message would, written as it is, be read by the target as something else: a LinuxCNC active comment such as `(LOGOPEN,..)`, `(PY,..)` or `(MSG,..)`, a Klartext `~` that continues the block into the next line, a `%` that ends a tape, a parenthesis or a control character. The writer changed the character (the table is `<text>` in the target's dialect spec) and the comment stays a comment. Check the posted text.";
    TextTransliterated = "W0691", "text-transliterated", Warning,
        "characters the target cannot read, replaced by the nearest ASCII",
        "The target reads 7-bit text (its `<text charset=\"ascii\">`): letters with accents are written without them, other characters as `?`.";
    P21TooLarge = "E0813", "p21-too-large", Error,
        "a Part 21 file holding more instance data than cncc reads",
        "Read into memory, the file's instances and parameters would take more than 1.5 GB (about 30 million parameter values, or 10 million instances); cncc stops reading at the instance named and reports the file. ISO 14649 programs are far smaller; a file this large is usually a geometry export or a broken generator.";
    LintFeedSpindleStopped = "W0701", "feed-with-spindle-stopped", Warning,
        "a cutting move while the spindle is stopped",
        "A feed move (G1, G2, G3, a cycle's feed) runs while the spindle is stopped: no M3/M4 since the start, a tool change or an M5. The control moves the tool into the part without turning it, which breaks the tool. Probing moves are not counted.\n\nBad:\n    T1 M6\n    G43 H1 Z5.\n    G1 Z-2. F100.   (spindle never started)\n\nGood:\n    T1 M6\n    S3000 M3\n    G43 H1 Z5.\n    G1 Z-2. F100.";
    LintNoLengthOffset = "W0702", "no-length-offset-after-tool-change", Warning,
        "a tool change without a length offset before the first Z move",
        "After a tool change the program moves Z before it activates a tool length offset (G43 H). On controls whose spec says the program must activate the length offset (capability `length-offset-programmed`: Fanuc, Haas), Z then runs with no offset or the previous tool's, and a longer tool crashes. Siemens (D with T) and Heidenhain (TOOL CALL) apply the length with the tool call; LinuxCNC machines often touch off each tool in the work offset instead of G43; they are not checked. An `H..` alone while G43 is in force counts as the new offset.\n\nBad:\n    T2 M6\n    G0 X0 Y0 Z5.\n\nGood:\n    T2 M6\n    G0 G43 H2 X0 Y0 Z5.";
    LintLengthOffsetOtherTool = "W0703", "length-offset-of-other-tool", Warning,
        "a length offset taken from another tool than the one in the spindle",
        "G43 names a length register (H) that is not the tool in the spindle. On controls whose spec says the H register names a tool (capability `length-register-names-tool`: LinuxCNC reads tool H's table length; Fanuc and Haas shops number H as T), the tool runs with another tool's length: a longer tool crashes. Shops that number offsets otherwise ignore this rule.\n\nBad:\n    T3 M6\n    G43 H5 Z25.\n\nGood:\n    T3 M6\n    G43 H3 Z25.";
    LintNoProgramEnd = "W0704", "missing-program-end", Warning,
        "a main program that runs to its last block without M2/M30",
        "The program runs off its last block without a program end (M2, M30; M99 in a subprogram; END PGM). Depending on the control it stops with spindle and coolant on, with modal states left for the next program, or waits for more tape. (On controls whose spec requires an end, this is already an error, E0305.)\n\nBad:\n    G0 Z50.\n    (end of file)\n\nGood:\n    G0 Z50.\n    M30";
    LintMoveAfterEnd = "W0705", "move-after-program-end", Warning,
        "moves written after the program end are never run",
        "M2/M30 ends the program, yet moves follow it that no jump or call reaches. They are never cut: usually an end left in the middle by an edit or by joining programs. (Files with jumps or local subprograms after the end are not checked.)\n\nBad:\n    G1 X10. F200.\n    M30\n    G1 X20.\n\nGood:\n    G1 X10. F200.\n    G1 X20.\n    M30";
    LintIncrementalToolChange = "W0706", "incremental-across-tool-change", Warning,
        "the first move after a tool change runs in incremental mode",
        "G91 was left on through a tool change (often from `G91 G28 Z0`), and the new tool's first move is incremental. A program written in absolute coordinates then moves by its coordinates instead of to them.\n\nBad:\n    G91 G28 Z0.\n    T2 M6\n    G0 X10. Y10.\n\nGood:\n    G91 G28 Z0.\n    T2 M6\n    G90 G0 X10. Y10.";
    LintIncrementalCall = "W0707", "incremental-into-subprogram", Warning,
        "a subprogram moves in incremental mode left on by its caller",
        "The caller left G91 on (not in the calling block), and the subprogram moves without setting G90 or G91 itself: it moves relatively where it was probably written absolute. Off by default: incremental subprograms for repeated patterns are a common, correct use.\n\nBad:\n    G91 G0 X10.\n    M98 P100   (O100 moves G0 X5 Y5 assuming G90)\n\nGood:\n    G90\n    M98 P100";
    LintIncrementalAfterReturn = "W0708", "incremental-after-reference-return", Warning,
        "G91 of a G91 G28 left on for the next move",
        "`G91 G28 Z0` returns to the reference point and leaves G91 on. The next move (not another reference return) then runs incremental, where it was meant absolute.\n\nBad:\n    G91 G28 Z0.\n    G0 X0 Y0\n\nGood:\n    G91 G28 Z0.\n    G90 G0 X0 Y0";
    LintRapidBelowCut = "W0709", "rapid-below-cut", Warning,
        "a rapid goes below the lowest height the tool has cut",
        "A rapid move goes lower on Z than any feed move of this tool since the tool change, with no feed move between: the tool rapids into material it has not cut. Usually a wrong Z, a missing retract or a lost G1. Only in the XY plane, only over the area the tool has cut (the box round its feed moves); cycle blocks are checked by W0712. Off by default: without a model of the stock cncc cannot tell air from material, and CAM systems step down from the air beside the part (a rapid to just above the next level) all the time.\n\nBad:\n    G1 Z-2. F100.\n    G0 Z5.\n    G0 X50.\n    G0 Z-5.\n\nGood:\n    G1 Z-2. F100.\n    G0 Z5.\n    G0 X50.\n    G0 Z1.\n    G1 Z-5. F100.";
    LintNoUnits = "W0710", "no-units", Warning,
        "a program that moves without ever setting its units",
        "The program never sets its units (G20/G21, G70/G71, TNC MM/INCH), so it runs in whatever units the control was left in by the last program or by its parameter. An inch program on a control left in mm cuts 25.4 times too small, and the other way round crashes. Off by default: many shops set the units at the machine (a parameter or setting) and never in the program; select it where programs move between machines.\n\nBad:\n    G90 G54\n    G0 X1. Y1.\n\nGood:\n    G21 G90 G54\n    G0 X1. Y1.";
    LintNoWorkOffset = "W0711", "no-work-offset", Warning,
        "a program that moves without ever selecting a work offset",
        "The program never selects a work offset (G54..G59, G154, G505.., G500), so it cuts in whichever the control has active. Applies to dialects whose spec has work-offset codes. Off by default: many shops set the work offset at the machine on purpose.\n\nBad:\n    G21 G90\n    G0 X0 Y0\n\nGood:\n    G21 G90 G54\n    G0 X0 Y0";
    LintCycleRBelowCut = "W0712", "cycle-r-below-cut", Warning,
        "a canned cycle whose R plane is below the lowest cut of this tool",
        "The cycle rapids to its R plane, and the R plane is lower than any feed move of this tool since the tool change: the rapid goes into material not cut yet. Usually an R given incrementally by mistake or a sign error.\n\nBad:\n    G1 Z-1. F100.\n    G0 Z5.\n    G81 X10. Y10. Z-10. R-3. F80.\n\nGood:\n    G1 Z-1. F100.\n    G0 Z5.\n    G81 X10. Y10. Z-10. R2. F80.";
    LintPeckTooDeep = "W0713", "peck-too-deep", Warning,
        "a peck drilling step deeper than 3 tool diameters",
        "The peck depth (Q of G83/G73) is larger than the tool diameter times a factor (3 by default; `[lint.peck-too-deep] max-diameters` in cncc.toml). Chips pack and small drills break. Checked only when the tool's diameter is known (a tool table or the program's tool list).\n\nBad:\n    (T1 D=3 drill)\n    G83 Z-30. R2. Q15. F60.\n\nGood:\n    G83 Z-30. R2. Q6. F60.";
    LintStopWithoutMessage = "W0714", "stop-without-message", Warning,
        "an M0/M1 stop with no message before it",
        "The program stops (M0, or M1 with optional stop on) and nothing tells the operator why: no comment or message in the stop's block or the block before. Shops that want each stop explained select this rule; off by default.\n\nBad:\n    G0 Z50.\n    M0\n\nGood:\n    G0 Z50.\n    (TURN THE PART OVER)\n    M0";
    LintCuttingWithoutCoolant = "W0715", "cutting-without-coolant", Warning,
        "a tool cuts with coolant off after an earlier tool cut with it on",
        "An earlier tool of the program cut with coolant (M7/M8) on, and this tool cuts with all coolant off: often an M8 forgotten after the tool change. Off by default: dry cutting (cast iron, graphite, some finishing passes) is a choice.\n\nBad:\n    T1 M6\n    S1000 M3 M8\n    G1 Z-1. F100.\n    T2 M6\n    S1000 M3\n    G1 Z-1. F100.\n\nGood:\n    T2 M6\n    S1000 M3 M8\n    G1 Z-1. F100.";
    LintSpindleSpeedZero = "W0716", "spindle-speed-zero", Warning,
        "a cutting move with the spindle on at speed 0",
        "The spindle is switched on (M3/M4) but the program set the speed to 0 (`S0 M3`, `TOOL CALL 1 Z S0`), so the tool does not turn while it cuts. Usually a post that lost the speed of a tool. A program that never gives S runs at the control's last speed, which cncc cannot know: not reported.\n\nBad:\n    T1 M6\n    S0 M3\n    G1 Z-1. F100.\n\nGood:\n    T1 M6\n    S3000 M3\n    G1 Z-1. F100.";
    LintSpeedForTool = "W0717", "speed-absurd-for-tool", Warning,
        "a spindle speed far outside what any tool of this diameter runs at",
        "The tool cuts at a surface speed (pi x diameter x S) above 2500 m/min or below 1 m/min: no tool material cuts there. Usually a speed for another tool, a lost digit, or S given for a tool of another size. The diameter comes from the tool table or the program's tool list; tools of unknown size, constant surface speed (G96) and a spindle never given S are not checked. The limits are the shop's: `[lint.speed-absurd-for-tool] max-surface-speed`, `min-surface-speed` (m/min) in cncc.toml.\n\nBad:\n    (T1 D=20. FLAT END MILL)\n    T1 M6\n    S60000 M3      (3770 m/min)\n    G1 Z-1. F500.\n\nGood:\n    T1 M6\n    S8000 M3       (503 m/min)\n    G1 Z-1. F500.";
    LintFeedForTool = "W0718", "feed-absurd-for-tool", Warning,
        "a cutting feed per spindle revolution far beyond the tool's size",
        "The tool advances more per spindle revolution (F / S, or F in G95) than half its diameter: the chip load is beyond any tool (a high-feed mill takes about 0.15 x D per revolution, a tap its pitch). Usually a feed for inch written in a metric program, a lost decimal point, or a speed for another tool. Checked at the first such cut of each tool, when the tool's diameter and the speed are known. The limit is the shop's: `[lint.feed-absurd-for-tool] max-feed-per-rev` (in tool diameters, default 0.5).\n\nBad:\n    (T1 D=6. FLAT END MILL)\n    T1 M6\n    S1000 M3\n    G1 Z-1. F5000.   (5 mm per revolution)\n\nGood:\n    S10000 M3\n    G1 Z-1. F1200.   (0.12 mm per revolution)";
    LintOtherUnit = "W0719", "values-look-like-other-unit", Warning,
        "values that look like the other unit: mm in an inch program, inch in a metric one",
        "An inch program (G20, G70, INCH) cuts more than 20 in (508 mm) from the work zero in Z or 120 in in X/Y, as mm values read as inches do (`Z-25.` in inch is 635 mm deep); or a metric program (one that sets G21, G71 or MM itself) cuts only within 25 mm of its work zero at feeds of 50 mm/min or less, as inch values read as mm do (a program that never sets its units gets this as a note on W0710 instead: it is right on a control left in inch). The units word or the post is probably wrong: the machine cuts 25.4 times too large or too small. The limits are the shop's: `[lint.values-look-like-other-unit] inch-max-z`, `inch-max-xy` (in), `metric-max-feed` (mm/min), `metric-max-size` (mm).\n\nBad:\n    G20 G90 G54\n    G1 Z-25. F200.\n\nGood:\n    G21 G90 G54\n    G1 Z-25. F200.";
    RapidIntoStock = "E1001", "rapid-into-stock", Error,
        "a rapid move cuts into the stock",
        "With the stock known (`--stock LxWxH[+X+Y+Z]`, or the program's `BLK FORM`), cncc simulates the material the program removes (docs/simulate.md) and probes every rapid before it moves: material standing more than 0.01 mm above the tool's surface along the rapid is a crash at rapid traverse. The tool's size comes from the tool table or the program's tool list; a tool whose size cncc would have to invent is checked along its axis only. The tool's side gets a little play (0.02 mm or half a grid cell), so a rapid along a wall the tool has just cut is not reported.\n\nBad (stock 100x50x20, top at Z0):\n    G0 X10. Y10.\n    G0 Z-2.\n\nGood:\n    G0 X10. Y10.\n    G0 Z2.\n    G1 Z-2. F100.";
    MaterialDiffers = "E1002", "material-differs", Error,
        "the port cuts another part than the source",
        "`cncc port --verify` (always with `--features`) cuts the same stock with the source and with the ported program (docs/simulate.md) and compares the finished parts cell by cell. A cell where the two parts' heights differ by more than the tolerance (0.01 mm) means the port does not cut the same part: the port is not written. The message gives the largest deviation, where it is, the move of each program that last cut there, and the volume only one of them removed. A pocket cycle that clears an island the source left standing is the classic case.";
    MaterialCheckStopped = "W1003", "material-check-stopped", Note,
        "the rapid and plunge checks stop: a tool of unknown size cut the stock",
        "The checks against the stock (E1001 rapid into the stock, W1004 plunge) need to know what material is left. A tool whose size cncc does not know (no `--tool-table` row, no CAM tool list, no `TOOL DEF` read before the run) is simulated as its axis line only, so after it has cut, the simulation leaves more material standing than the real tool does, and a rapid or a plunge into it is no longer certain. The checks stop at its first cut, said once with the block. Give the tools' sizes (`--tool-table`) to check the whole program. They also stop at a tilted working plane the run does not make (W0518: PLANE SPATIAL, cycle 19): the positions after it are the untilted ones, not the machine's.";
    PlungeWithoutCentreCutting = "W1004", "plunge-without-centre-cutting", Warning,
        "a flat end mill fed straight down into solid material",
        "With the stock known (`--stock`, or the program's `BLK FORM`), a feed straight down the tool axis (a pure -Z move) of a flat end mill whose centre goes into material that no earlier cut removed. An end mill without centre-cutting edges cannot cut under its centre: it rubs, chips or breaks. A drill, a ball or bull nose mill, a tool with a point angle, and a tool whose name says it plunges (drill, tap, reamer, boring, counterbore, plunge, centre cutting) are not reported; neither is a ramp or a helix, nor a plunge into a hole cut before. The first plunge of each tool is shown with how many it makes. The tool's shape comes from the tool table's comment or the program's CAM tool list.\n\nBad (flat end mill):\n    G0 X10. Y10. Z2.\n    G1 Z-5. F100.\n\nGood:\n    G0 X10. Y10. Z2.\n    G1 X20. Z-5. F100.   (a ramp)";
    LatheProfileFailed = "E0547", "lathe-profile-failed", Error,
        "a lathe profile cycle (G70/G71/G72) cannot be made from its contour",
        "LinuxCNC's G70 (finishing), G71 (roughing along Z) and G72 (facing) read the contour from the subroutine named by Q and cut towards it from the block's X Z. The contour must run one way in Z (and, for G72, in X) without turning back: every element moves away from the start, arcs stay on one side of their centre. D (the finishing allowance) offsets it; I (the depth of cut) must be greater than zero; a corner rounded with A or broken with C needs room between its neighbours. The message is LinuxCNC's (`G7X error: ...`). cncc also stops where the roughing passes would never end (LinuxCNC 2.9 loops for ever there).";
}

impl Code {
    /// Finds a code by its code (`E0201`, case-insensitive) or its name.
    pub fn lookup(text: &str) -> Option<Code> {
        let t = text.trim();
        Code::ALL
            .iter()
            .copied()
            .find(|c| c.code().eq_ignore_ascii_case(t) || c.name().eq_ignore_ascii_case(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_and_names_are_unique() {
        let mut codes: Vec<_> = Code::ALL.iter().map(|c| c.code()).collect();
        let mut names: Vec<_> = Code::ALL.iter().map(|c| c.name()).collect();
        codes.sort();
        names.sort();
        let n = codes.len();
        codes.dedup();
        names.dedup();
        assert_eq!(codes.len(), n, "duplicate code");
        assert_eq!(names.len(), n, "duplicate name");
    }

    #[test]
    fn lookup_by_code_and_name() {
        assert_eq!(Code::lookup("e0201"), Some(Code::TwoMotionCodes));
        assert_eq!(Code::lookup("two-motion-codes"), Some(Code::TwoMotionCodes));
        assert_eq!(Code::lookup("E9999"), None);
    }
}
