//! Writing explicit toolpaths: toolpath lists, cutter location
//! trajectories, feed stops.

use super::*;

impl<'p> W<'p> {
    pub fn opt_toolpath_list(&mut self, t: &Option<Vec<Toolpath>>) -> Value {
        opt(t.as_ref().map(|t| self.toolpath_list(t)))
    }

    pub fn toolpath_list(&mut self, t: &[Toolpath]) -> Value {
        let items = list(t.iter().map(|tp| self.toolpath(tp)).collect());
        self.add("TOOLPATH_LIST", vec![items])
    }

    fn toolpath(&mut self, t: &Toolpath) -> Value {
        match t {
            Toolpath::CutterLocation {
                base,
                direction,
                basic_curve,
                tool_axis,
                surface_normal,
            } => {
                let mut params = self.toolpath_base(base);
                params.push(ob(*direction));
                params.push(self.curve(basic_curve));
                params.push(self.opt_curve(tool_axis));
                params.push(self.opt_curve(surface_normal));
                self.add("CUTTER_LOCATION_TRAJECTORY", params)
            }
            Toolpath::Feedstop { base, dwell } => {
                let mut params = self.toolpath_base(base);
                params.push(r(*dwell));
                self.add("FEEDSTOP", params)
            }
            Toolpath::Other(raw) => self.raw(raw),
        }
    }

    fn toolpath_base(&mut self, b: &ToolpathBase) -> Vec<Value> {
        let kind = match &b.kind {
            ToolpathType::Approach => "APPROACH",
            ToolpathType::Lift => "LIFT",
            ToolpathType::Connect => "CONNECT",
            ToolpathType::NonContact => "NON_CONTACT",
            ToolpathType::Contact => "CONTACT",
            ToolpathType::TrajectoryPath => "TRAJECTORY_PATH",
            ToolpathType::Other(o) => o,
        };
        let speed = match &b.speed {
            None => Value::Null,
            Some(ToolpathSpeed::Ratio(v)) => {
                Value::Typed("POSITIVE_RATIO_MEASURE".into(), Box::new(Param::new(r(*v))))
            }
            Some(ToolpathSpeed::Named(n)) => {
                Value::Typed("SPEED_NAME".into(), Box::new(Param::new(e(n))))
            }
            Some(ToolpathSpeed::Other(raw)) => self.raw(raw),
        };
        vec![
            bool_value(b.priority),
            e(kind),
            speed,
            opt(b.technology.as_ref().map(|t| self.technology(t))),
            opt(b
                .machine_functions
                .as_ref()
                .map(|m| self.machine_functions(m))),
        ]
    }
}
