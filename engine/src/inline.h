// DEM_INLINE marks the small functions of a contact's calculation (the
// laws, the geometry, the tangential helpers). The force pass over packed
// rows (contact_batch.h) becomes vector code only if its loop holds no
// call, so these must be inlined there whatever the compiler's size budget
// says.
#pragma once

#define DEM_INLINE [[gnu::always_inline]] inline
// The same for a lambda (written after its parameters): a visitor of a
// field list (particle_fields.h) in a loop that must stay free of calls.
#define DEM_INLINE_LAMBDA __attribute__((always_inline))
