//! What observers have accumulated, as flat numbers, for a run's checkpoint:
//! a run continued from it must end with the same results, bit for bit, as
//! one never stopped. Numbers are kept as f64 (counts and lengths below
//! 2^53 are exact), so a state is a plain list the runner stores as bits.

/// Appends an observer's state.
#[derive(Debug, Default)]
pub struct StateOut(pub Vec<f64>);

impl StateOut {
    pub fn number(&mut self, x: f64) {
        self.0.push(x);
    }

    /// A list: its length, then its values.
    pub fn list(&mut self, values: &[f64]) {
        self.0.push(values.len() as f64);
        self.0.extend_from_slice(values);
    }
}

/// Reads an observer's state back, in the order it was written.
#[derive(Debug)]
pub struct StateIn<'a> {
    data: &'a [f64],
    at: usize,
}

impl<'a> StateIn<'a> {
    pub fn new(data: &'a [f64]) -> Self {
        StateIn { data, at: 0 }
    }

    pub fn number(&mut self) -> Result<f64, String> {
        let x = *self
            .data
            .get(self.at)
            .ok_or("the observers' state ends early")?;
        self.at += 1;
        Ok(x)
    }

    pub fn list(&mut self) -> Result<Vec<f64>, String> {
        let n = self.number()?;
        let end = self.at + n as usize;
        if n < 0.0 || n.fract() != 0.0 || end > self.data.len() {
            return Err(format!(
                "the observers' state holds a list of {n} values that is not there"
            ));
        }
        let values = self.data[self.at..end].to_vec();
        self.at = end;
        Ok(values)
    }

    /// All read: a state with more in it belongs to other observers.
    pub fn done(&self) -> Result<(), String> {
        if self.at == self.data.len() {
            Ok(())
        } else {
            Err("the observers' state holds more than these observers".into())
        }
    }
}
