//! A typed arena: values stored once, referred to by copyable handles.

use serde::Serialize;
use std::marker::PhantomData;

/// An index into an [`Arena<T>`].
#[derive(Serialize)]
#[serde(transparent)]
pub struct Handle<T> {
    index: u32,
    #[serde(skip)]
    _marker: PhantomData<fn() -> T>,
}

impl<T> Handle<T> {
    pub fn index(self) -> usize {
        self.index as usize
    }
}

impl<T> Clone for Handle<T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for Handle<T> {}
impl<T> PartialEq for Handle<T> {
    fn eq(&self, o: &Self) -> bool {
        self.index == o.index
    }
}
impl<T> Eq for Handle<T> {}
impl<T> std::hash::Hash for Handle<T> {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        self.index.hash(h)
    }
}
impl<T> std::fmt::Debug for Handle<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "#{}", self.index)
    }
}

/// Values of one type, appended and never removed.
#[derive(Debug, Clone, Serialize)]
pub struct Arena<T> {
    items: Vec<T>,
}

impl<T> Default for Arena<T> {
    fn default() -> Self {
        Arena { items: Vec::new() }
    }
}

impl<T> Arena<T> {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn alloc(&mut self, value: T) -> Handle<T> {
        let index = u32::try_from(self.items.len()).expect("arena overflow");
        self.items.push(value);
        Handle {
            index,
            _marker: PhantomData,
        }
    }

    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Drops every value (handles given out before become invalid).
    pub fn clear(&mut self) {
        self.items.clear();
    }

    pub fn iter(&self) -> impl Iterator<Item = (Handle<T>, &T)> {
        self.iter_from(0)
    }

    /// The values from index `from` on, with their handles.
    pub fn iter_from(&self, from: usize) -> impl Iterator<Item = (Handle<T>, &T)> {
        let from = from.min(self.items.len());
        self.items[from..].iter().enumerate().map(move |(i, v)| {
            let i = i + from;
            (
                Handle {
                    index: i as u32,
                    _marker: PhantomData,
                },
                v,
            )
        })
    }
}

impl<T> std::ops::Index<Handle<T>> for Arena<T> {
    type Output = T;
    fn index(&self, h: Handle<T>) -> &T {
        &self.items[h.index as usize]
    }
}

impl<T> std::ops::IndexMut<Handle<T>> for Arena<T> {
    fn index_mut(&mut self, h: Handle<T>) -> &mut T {
        &mut self.items[h.index as usize]
    }
}
