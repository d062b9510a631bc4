//! The typed STEP-NC model: the ISO 14649-10/11/111 entities cncc uses,
//! in cncc's internal units. Part 21 files are read into it and written
//! from it (`super::part21` ↔ this), programs are raised into it (CC1
//! toolpaths, CC2 features), and the post-processors read it.
//!
//! Units inside the model (converted at the Part 21 boundary):
//! lengths mm, angles degrees, time s, feed mm/min, cutting speed m/min,
//! spindle rpm SIGNED AS THE MACHINE SEES IT: positive = clockwise (M3),
//! negative = counter-clockwise (M4). (ISO 14649 stores rev/s with the
//! opposite sign: positive = counter-clockwise; see `reference/stepnc.md`
//! §0.4.) Pressure Pa.
//!
//! Shared objects (workpieces, features, operations, tools) live in arenas
//! on the [`Project`] and are referred to by index; small value objects
//! (placements, planes, technology, machine functions) are held inline and
//! the writer shares equal ones. What the typed layer does not model is
//! kept as a [`Raw`] subtree, so nothing a file says is dropped.

/// A point or vector, mm.
pub type P3 = [f64; 3];

macro_rules! id_type {
    ($($name:ident),*) => {$(
        /// An index into the project's arena of that kind.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub struct $name(pub u32);
        impl $name {
            pub fn index(self) -> usize { self.0 as usize }
        }
    )*};
}
id_type!(WorkpieceId, FeatureId, OperationId, ToolId);

/// A whole ISO 14649 project.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Project {
    pub id: String,
    pub main_workplan: Workplan,
    /// The project's `its_workpieces`.
    pub its_workpieces: Vec<WorkpieceId>,
    pub owner: Option<Raw>,
    pub release: Option<Raw>,
    pub status: Option<Raw>,
    // ---- arenas
    pub workpieces: Vec<Workpiece>,
    pub features: Vec<Feature>,
    pub operations: Vec<Operation>,
    pub tools: Vec<Tool>,
}

impl Feature {
    /// The depth plane's z in the feature's frame (0 when unset).
    pub fn depth_z(&self) -> f64 {
        self.depth
            .as_ref()
            .map_or(0.0, |d| d.position.location.xyz[2])
    }
}

impl Project {
    pub fn feature(&self, id: FeatureId) -> &Feature {
        &self.features[id.index()]
    }
    pub fn operation(&self, id: OperationId) -> &Operation {
        &self.operations[id.index()]
    }
    pub fn tool(&self, id: ToolId) -> &Tool {
        &self.tools[id.index()]
    }
    pub fn workpiece(&self, id: WorkpieceId) -> &Workpiece {
        &self.workpieces[id.index()]
    }
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct Workplan {
    pub id: String,
    pub elements: Vec<Executable>,
    pub channel: Option<Raw>,
    pub setup: Option<Setup>,
    pub effect: Option<Raw>,
}

/// One element of a workplan, in execution order.
#[derive(Clone, Debug, PartialEq)]
pub enum Executable {
    Workingstep(MachiningWorkingstep),
    Rapid(RapidMovement),
    Workplan(Workplan),
    ProgramStop {
        id: String,
    },
    OptionalStop {
        id: String,
    },
    DisplayMessage {
        id: String,
        text: String,
    },
    /// Any other executable (selective, parallel, nc functions...).
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub struct MachiningWorkingstep {
    pub id: String,
    pub secplane: Plane,
    pub feature: FeatureId,
    pub operation: OperationId,
    pub effect: Option<Raw>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct RapidMovement {
    pub id: String,
    pub secplane: Plane,
    pub toolpath: Option<Vec<Toolpath>>,
    pub tool_direction: Option<Raw>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    pub id: String,
    pub origin: Option<Axis2Placement>,
    pub secplane: Plane,
    pub workpiece_setups: Vec<WorkpieceSetup>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct WorkpieceSetup {
    pub workpiece: WorkpieceId,
    pub origin: Axis2Placement,
    pub offset: Option<Raw>,
    pub restricted_area: Option<Raw>,
    pub instructions: Vec<Raw>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Workpiece {
    pub id: String,
    pub material: Option<Material>,
    /// `global_tolerance` (a shape_tolerance: a length, mm).
    pub global_tolerance: Option<f64>,
    pub rawpiece: Option<WorkpieceId>,
    pub geometry: Option<Raw>,
    pub bounding: Option<Bounding>,
    pub clamping_positions: Vec<Point>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub standard_identifier: String,
    pub material_identifier: String,
    pub properties: Vec<Raw>,
}

/// A workpiece's bounding geometry.
#[derive(Clone, Debug, PartialEq)]
pub enum Bounding {
    /// `BLOCK(name, position, x, y, z)`: a box from the position's origin.
    Block {
        name: String,
        position: Axis2Placement,
        size: P3,
    },
    Other(Raw),
}

// ---------------------------------------------------------------- geometry

#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub name: String,
    pub xyz: P3,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Direction {
    pub name: String,
    pub ratios: P3,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Axis2Placement {
    pub name: String,
    pub location: Point,
    /// The local Z axis (default +Z).
    pub axis: Option<Direction>,
    /// The local X axis (default +X).
    pub ref_direction: Option<Direction>,
}

/// An elementary surface used as a plane (security plane, depth plane).
/// Read from `PLANE` or `ELEMENTARY_SURFACE`; written as `PLANE`.
#[derive(Clone, Debug, PartialEq)]
pub struct Plane {
    pub name: String,
    pub position: Axis2Placement,
}

/// A bounded curve: toolpath geometry and general profiles.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    Polyline {
        name: String,
        points: Vec<Point>,
    },
    /// A `TRIMMED_CURVE` of a `CIRCLE` trimmed by points.
    Arc {
        name: String,
        /// The circle's centre and orientation (its axis is the arc's normal).
        circle: Axis2Placement,
        circle_name: String,
        radius: f64,
        start: Point,
        end: Point,
        /// `sense_agreement`: true = counter-clockwise about the axis.
        sense: bool,
    },
    /// A `TRIMMED_CURVE` of a `LINE`.
    Line {
        name: String,
        start: Point,
        end: Point,
        /// The LINE entity as read (point + vector), kept for the writer.
        basis: Raw,
    },
    Composite {
        name: String,
        segments: Vec<CompositeSegment>,
        self_intersect: Option<bool>,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub struct CompositeSegment {
    /// `transition_code` enumeration, as written (`CONTINUOUS`...).
    pub transition: String,
    pub same_sense: bool,
    pub curve: Curve,
}

/// A length with its tolerance.
#[derive(Clone, Debug, PartialEq)]
pub struct Toleranced {
    pub nominal: f64,
    pub tolerance: Tolerance,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Tolerance {
    PlusMinus {
        upper: f64,
        lower: f64,
        significant_digits: i64,
    },
    LimitsAndFits {
        deviation: f64,
        grade: f64,
        fitting: Option<String>,
    },
    Other(Raw),
    /// `$`: generators leave the tolerance of a nominal size unset.
    Unset,
}

// ---------------------------------------------------------------- features

#[derive(Clone, Debug, PartialEq)]
pub struct Feature {
    pub id: String,
    pub workpiece: WorkpieceId,
    pub operations: Vec<OperationId>,
    pub placement: Axis2Placement,
    /// The depth plane (below the placement for pockets and holes).
    /// Mandatory in ISO 14649-10, but generators leave it `$` on through
    /// holes (read as unknown, W0803; posting takes the stock's bottom for
    /// a through feature and refuses any other).
    pub depth: Option<Plane>,
    pub kind: FeatureKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum FeatureKind {
    PlanarFace {
        course_of_travel: TravelPath,
        removal_boundary: OpenProfile,
        face_boundary: Option<ClosedProfile>,
        bosses: Vec<Raw>,
    },
    RoundHole {
        diameter: Toleranced,
        change_in_diameter: Option<Raw>,
        bottom: HoleBottom,
    },
    ClosedPocket {
        pocket: PocketCommon,
        boundary: ClosedProfile,
    },
    OpenPocket {
        pocket: PocketCommon,
        open_boundary: OpenProfile,
        wall_boundary: Option<OpenProfile>,
    },
    Slot {
        course_of_travel: TravelPath,
        swept_shape: OpenProfile,
        end_conditions: Vec<SlotEnd>,
    },
    Step {
        open_boundary: TravelPath,
        wall_boundary: Option<OpenProfile>,
        bosses: Vec<Raw>,
    },
    GeneralOutsideProfile {
        swept_shape: TravelPath,
        boundary: Profile,
    },
    /// A feature known only by its explicit toolpaths.
    ToolpathFeature,
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub struct PocketCommon {
    pub bosses: Vec<Raw>,
    pub slope: Option<f64>,
    pub bottom: PocketBottom,
    pub planar_radius: Option<Toleranced>,
    pub orthogonal_radius: Option<Toleranced>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Profile {
    Closed(ClosedProfile),
    Open(OpenProfile),
}

#[derive(Clone, Debug, PartialEq)]
pub enum ClosedProfile {
    Rectangular {
        placement: Option<Axis2Placement>,
        width: Toleranced,
        length: Toleranced,
    },
    Circular {
        placement: Option<Axis2Placement>,
        diameter: Toleranced,
    },
    General {
        placement: Option<Axis2Placement>,
        shape: Curve,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub enum OpenProfile {
    /// `LINEAR_PROFILE(placement, NUMERIC_PARAMETER(name, value, unit))`.
    Linear {
        placement: Option<Axis2Placement>,
        length: NumericParameter,
    },
    /// Radii and angles are mandatory in ISO 14649-10, but generators
    /// leave them `$` (GRIMA's `SQUARE_U_PROFILE(#p,#w,$,$,$,$)`): read as
    /// unset (W0803). Posting reads an unset radius as no fillet asked
    /// and an unset angle as an upright wall; the angles are measured
    /// against the profile's z axis (0 upright; see `post::slots::upright`).
    SquareU {
        placement: Option<Axis2Placement>,
        width: Toleranced,
        first_radius: Option<Toleranced>,
        first_angle: Option<f64>,
        second_radius: Option<Toleranced>,
        second_angle: Option<f64>,
    },
    RoundedU {
        placement: Option<Axis2Placement>,
        width: Toleranced,
    },
    Vee {
        placement: Option<Axis2Placement>,
        radius: Toleranced,
        angle: f64,
        tilt_angle: f64,
    },
    PartialCircular {
        placement: Option<Axis2Placement>,
        radius: Toleranced,
        sweep_angle: f64,
    },
    General {
        placement: Option<Axis2Placement>,
        shape: Curve,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub struct NumericParameter {
    pub name: String,
    pub value: f64,
    pub unit: String,
}

#[derive(Clone, Debug, PartialEq)]
pub enum TravelPath {
    Linear {
        placement: Option<Axis2Placement>,
        distance: Toleranced,
        direction: Direction,
    },
    General {
        placement: Option<Axis2Placement>,
        path: Curve,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub enum HoleBottom {
    Through,
    Flat,
    FlatWithRadius {
        corner_radius: Toleranced,
    },
    Conical {
        tip_angle: f64,
        tip_radius: Option<Toleranced>,
    },
    Spherical {
        radius: Toleranced,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub enum PocketBottom {
    Planar,
    Through,
    Radiused,
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub enum SlotEnd {
    Open,
    Radiused,
    Loop,
    Flat {
        corner_radius1: Toleranced,
        corner_radius2: Toleranced,
    },
    Woodruff {
        radius: Toleranced,
    },
    Other(Raw),
}

// -------------------------------------------------------------- operations

#[derive(Clone, Debug, PartialEq)]
pub struct Operation {
    pub id: String,
    pub toolpath: Option<Vec<Toolpath>>,
    pub tool_direction: Option<Raw>,
    pub retract_plane: Option<f64>,
    pub start_point: Option<Point>,
    pub tool: ToolId,
    pub technology: Technology,
    pub machine_functions: MachineFunctions,
    pub overcut_length: Option<f64>,
    pub kind: OperationKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum OperationKind {
    /// PLANE_ROUGH_MILLING / PLANE_FINISH_MILLING.
    PlaneMilling {
        finish: bool,
        milling: MillingCommon,
        axial_cutting_depth: Option<f64>,
        allowance_bottom: Option<f64>,
    },
    /// SIDE_ROUGH_MILLING / SIDE_FINISH_MILLING.
    SideMilling {
        finish: bool,
        milling: MillingCommon,
        axial_cutting_depth: Option<f64>,
        radial_cutting_depth: Option<f64>,
        allowance_side: Option<f64>,
    },
    /// BOTTOM_AND_SIDE_ROUGH_MILLING / BOTTOM_AND_SIDE_FINISH_MILLING.
    BottomAndSideMilling {
        finish: bool,
        milling: MillingCommon,
        axial_cutting_depth: Option<f64>,
        radial_cutting_depth: Option<f64>,
        allowance_side: Option<f64>,
        allowance_bottom: Option<f64>,
    },
    Freeform {
        approach: Option<ApproachRetract>,
        retract: Option<ApproachRetract>,
        strategy: Option<Raw>,
    },
    Drilling(DrillCommon),
    CenterDrilling(DrillCommon),
    CounterSinking(DrillCommon),
    MultistepDrilling {
        drill: DrillCommon,
        retract_distance: f64,
        first_depth: f64,
        depth_of_step: f64,
        dwell_time_step: Option<f64>,
    },
    /// REAMING / BORING.
    Boring {
        reaming: bool,
        drill: DrillCommon,
        spindle_stop_at_bottom: bool,
        depth_of_testcut: Option<f64>,
        waiting_position: Option<Point>,
    },
    /// TAPPING (ISO 14649-11): a tap fed in and out with the spindle
    /// synchronised to the feed. The thread pitch is the technology's
    /// feed over its spindle speed (`synchronize_spindle_with_feed` set),
    /// see [`Operation::thread_pitch`]; the hand is the spindle's sign
    /// (negative = M4 = left-hand thread) and the TAP body's `hand_of_cut`.
    Tapping {
        drill: DrillCommon,
        /// True: the tap sits in a floating (compensating) chuck, so the
        /// controller need not synchronise the spindle exactly.
        compensation_chuck: bool,
    },
    /// THREAD_DRILLING (ISO 14649-11): drilling and threading in one tool.
    ThreadDrilling {
        drill: DrillCommon,
        helical_movement_on_forward: bool,
    },
    Other(Raw),
}

impl Operation {
    /// The thread pitch of a tapping operation, mm per revolution: the
    /// feed over the spindle speed (ISO 14649 has no pitch attribute on the
    /// TAP body in the schema we follow: `machinetool_resource_schema9`
    /// gives TAP only the five milling_machine_tool_body attributes).
    pub fn thread_pitch(&self) -> Option<f64> {
        match self.kind {
            OperationKind::Tapping { .. } | OperationKind::ThreadDrilling { .. } => {
                let feed = self.technology.feed?;
                let rpm = self.technology.spindle?.abs();
                (rpm > 0.0).then(|| feed / rpm)
            }
            _ => None,
        }
    }
}

/// What every two5D milling operation has beyond the machining operation.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct MillingCommon {
    pub approach: Option<ApproachRetract>,
    pub retract: Option<ApproachRetract>,
    pub strategy: Option<Strategy>,
}

/// What every drilling-type operation has beyond the machining operation.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct DrillCommon {
    pub cutting_depth: Option<f64>,
    pub previous_diameter: Option<f64>,
    pub dwell_time_bottom: Option<f64>,
    pub feed_on_retract: Option<f64>,
    pub strategy: Option<DrillingStrategy>,
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct DrillingStrategy {
    pub reduced_cut_at_start: Option<f64>,
    pub reduced_feed_at_start: Option<f64>,
    pub depth_of_start: Option<f64>,
    pub reduced_cut_at_end: Option<f64>,
    pub reduced_feed_at_end: Option<f64>,
    pub depth_of_end: Option<f64>,
}

/// A two5D milling strategy. `overlap` as the file gives it (a ratio;
/// some generators write percentages > 1).
#[derive(Clone, Debug, PartialEq)]
pub enum Strategy {
    Unidirectional {
        base: StrategyBase,
        feed_direction: Option<Direction>,
        cutmode: Option<CutMode>,
    },
    Bidirectional {
        base: StrategyBase,
        feed_direction: Option<Direction>,
        stepover_direction: Option<LeftOrRight>,
        stroke_connection: Option<String>,
    },
    ContourParallel {
        base: StrategyBase,
        rotation: Option<RotDirection>,
        cutmode: Option<CutMode>,
    },
    /// BIDIRECTIONAL_CONTOUR and CONTOUR_BIDIRECTIONAL (same attributes).
    BidirectionalContour {
        contour_first: bool,
        base: StrategyBase,
        feed_direction: Option<Direction>,
        stepover_direction: Option<LeftOrRight>,
        rotation: Option<RotDirection>,
        cutmode: Option<CutMode>,
    },
    ContourSpiral {
        base: StrategyBase,
        rotation: Option<RotDirection>,
        cutmode: Option<CutMode>,
    },
    CenterMilling {
        base: StrategyBase,
    },
    Explicit {
        base: StrategyBase,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct StrategyBase {
    pub overlap: Option<f64>,
    pub allow_multiple_passes: Option<bool>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CutMode {
    Climb,
    Conventional,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RotDirection {
    Cw,
    Ccw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LeftOrRight {
    Left,
    Right,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ApproachRetract {
    PlungeToolaxis {
        orientation: Option<Direction>,
    },
    PlungeRamp {
        orientation: Option<Direction>,
        angle: f64,
    },
    PlungeHelix {
        orientation: Option<Direction>,
        radius: f64,
        angle: f64,
    },
    PlungeZigzag {
        orientation: Option<Direction>,
        angle: f64,
        width: f64,
    },
    RetractAngle {
        orientation: Option<Direction>,
        angle: f64,
        travel_length: f64,
    },
    RetractTangent {
        orientation: Option<Direction>,
        radius: f64,
    },
    AlongPath {
        orientation: Option<Direction>,
        path: Vec<Toolpath>,
    },
    Other(Raw),
}

/// MILLING_TECHNOLOGY, in model units.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Technology {
    /// mm/min.
    pub feed: Option<f64>,
    /// `feedrate_reference`: true = tool centre point (TCP), false = CCP.
    pub feed_at_tcp: bool,
    /// m/min.
    pub cut_speed: Option<f64>,
    /// rpm, positive clockwise (M3).
    pub spindle: Option<f64>,
    /// mm.
    pub feed_per_tooth: Option<f64>,
    pub synchronize_spindle_with_feed: bool,
    pub inhibit_feedrate_override: bool,
    pub inhibit_spindle_override: bool,
    pub adaptive_control: Option<Raw>,
}

/// MILLING_MACHINE_FUNCTIONS.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct MachineFunctions {
    pub coolant: bool,
    pub coolant_pressure: Option<f64>,
    pub mist: Option<bool>,
    pub through_spindle_coolant: bool,
    pub through_pressure: Option<f64>,
    pub axis_clamping: Vec<String>,
    pub chip_removal: bool,
    pub oriented_spindle_stop: Option<Direction>,
    pub process_model: Option<Raw>,
    pub other_functions: Vec<Raw>,
}

// ---------------------------------------------------------------- toolpaths

#[derive(Clone, Debug, PartialEq)]
pub enum Toolpath {
    CutterLocation {
        base: ToolpathBase,
        direction: Option<bool>,
        basic_curve: Curve,
        tool_axis: Option<Curve>,
        surface_normal: Option<Curve>,
    },
    Feedstop {
        base: ToolpathBase,
        /// s.
        dwell: f64,
    },
    Other(Raw),
}

#[derive(Clone, Debug, PartialEq)]
pub struct ToolpathBase {
    pub priority: bool,
    pub kind: ToolpathType,
    pub speed: Option<ToolpathSpeed>,
    pub technology: Option<Technology>,
    pub machine_functions: Option<MachineFunctions>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ToolpathType {
    Approach,
    Lift,
    Connect,
    NonContact,
    Contact,
    TrajectoryPath,
    Other(String),
}

#[derive(Clone, Debug, PartialEq)]
pub enum ToolpathSpeed {
    /// `POSITIVE_RATIO_MEASURE(r)`: a ratio of the technology's feed.
    Ratio(f64),
    /// `SPEED_NAME(.RAPID.)`.
    Named(String),
    Other(Raw),
}

// -------------------------------------------------------------------- tools

#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    pub id: String,
    pub body: ToolBody,
    pub cutting_edges: Vec<CuttingComponent>,
    pub overall_assembly_length: Option<f64>,
    pub direction_for_spindle_orientation: Option<Direction>,
    pub holder_diameter_for_spindle_orientation: Option<f64>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct CuttingComponent {
    /// Mandatory in ISO 14649-111, but generators leave it `$` (GRIMA's
    /// `CUTTING_COMPONENT($,$,$,$,$)`): read as unknown (W0803) rather
    /// than dropping the tool and the workingstep with it.
    pub tool_offset_length: Option<f64>,
    pub material: Option<Raw>,
    pub technological_data: Option<Raw>,
    pub expected_tool_life: Option<f64>,
    pub technology: Option<Technology>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ToolBody {
    pub kind: ToolBodyKind,
    pub dimension: ToolDimension,
    pub number_of_teeth: Option<i64>,
    pub hand_of_cut: Option<Hand>,
    pub coolant_through_tool: Option<bool>,
    pub pilot_length: Option<f64>,
    /// Attributes after the common five that this body type adds, as read.
    pub extra: Vec<RawValue>,
}

/// The tool body's entity (14649-111), canonical spelling.
#[derive(Clone, Debug, PartialEq)]
pub enum ToolBodyKind {
    Endmill,
    TaperedEndmill,
    BallEndmill,
    BullnoseEndmill,
    Facemill,
    TwistDrill,
    TaperedDrill,
    CenterDrill,
    Spotdrill,
    Countersink,
    Counterbore,
    Reamer,
    TaperedReamer,
    Tap,
    ThreadMill,
    /// Any other body entity, by its name.
    Other(String),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hand {
    Left,
    Right,
    Neutral,
}

/// MILLING_TOOL_DIMENSION, mm and degrees.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ToolDimension {
    pub diameter: f64,
    pub tip_half_angle: Option<f64>,
    pub circumference_angle: Option<f64>,
    pub cutting_edge_length: Option<f64>,
    pub edge_radius: Option<f64>,
    pub edge_center_vertical: Option<f64>,
    pub edge_center_horizontal: Option<f64>,
}

// ---------------------------------------------------------------------- raw

/// An instance the typed layer does not model, with its parameters;
/// references are followed and held inline.
#[derive(Clone, Debug, PartialEq)]
pub struct Raw {
    pub entity: String,
    pub params: Vec<RawValue>,
}

/// One Part 21 parameter value.
#[derive(Clone, Debug, PartialEq)]
pub enum RawValue {
    Integer(i64),
    Real(f64),
    String(String),
    Enum(String),
    Bool(bool),
    /// `$`.
    Null,
    /// `*`.
    Derived,
    List(Vec<RawValue>),
    /// `TYPE_NAME(value)`.
    Typed(String, Box<RawValue>),
    /// A referenced instance.
    Instance(Box<Raw>),
}
