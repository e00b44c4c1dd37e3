# What the sandbox says: messages in the strip, notes under fields, errors.

number-not-a-number = not a number
discs-count = { $count ->
    [one] 1 disc
   *[other] { $count } discs
}

## Counts and lessons
count-line = collisions: { $pairs } between discs
count-line-walls = collisions: { $pairs } between discs · { $walls } with walls
pi-result = { $count } collisions: π ≈ { $pi }
pi-count = { $count ->
    [one] 1 collision
   *[other] { $count } collisions
}

## What a method cannot promise
warning-verlet = verlet: collisions lose energy; the restitution e = { $restitution } is not honoured
warning-seed = seed: fast discs can pass through each other
warning-substeps = fast discs can pass through each other: the fastest moves { $radii }× its radius in one small step ({ $substeps ->
    [one] 1 substep
   *[other] { $substeps } substeps
} per step; more of them, under More, prevent it)
warning-stall = { $method }: too many collisions at once, so time has stopped. Undo takes back the change that caused it; to go on as it is, choose the method impulse (under More)

## Scenes and files
file-cannot-create = cannot create { $folder }: { $error }
file-cannot-write = cannot write { $file }: { $error }
scene-cannot-open = Cannot open { $file }: { $error }
scene-opened = Opened { $name }
scene-opened-undo = Opened { $name }. { $undo } brings back { $previous } as you left it
scene-kept = { $error } (kept the current scene)
scene-not-found = There is no scene file { $name }, here or in { $folder } (kept the current scene)
scene-reset = Scene reset
scene-reset-edits = Scene reset to how it opened, without your edits: { $undo } brings them back
scene-back-to-setup = Back to your set-up at t = { $time } s; { $reset } again: the scene as it opened
scene-cannot-reset = Cannot reset: { $error }
scene-cleared = Cleared: drag on empty space to launch discs
scene-path-empty = Type the path of a scene file first
scene-downloaded = Downloaded { $file }
scene-saved = Saved { $file } in { $folder }
scene-saved-short = Saved { $file }
scene-saved-at = { $saved }, the discs as they are at t = { $time } s
scene-renamed = The scene is called { $name } now
scene-name-empty = A name needs a letter or a digit
scene-not-saved = Not saved: { $error }
screenshot-saved = Screenshot saved: { $file }
screenshot-downloaded = Screenshot downloaded: { $file }
screenshot-not-saved = Screenshot not saved: { $error }
scene-shared = The page's address now opens this scene: copy it from the address bar and send it
scene-not-shared = Not shared: { $error }
undone = Undone: { $what } (Ctrl+Shift+Z or Ctrl+Y redoes it)
nothing-to-undo = Nothing to undo
redone = Redone: { $what }
nothing-to-redo = Nothing to redo

## What undo names
edit-open-scene = open a scene
edit-reset = reset
edit-rename = the scene's name
edit-clear = clear
edit-restitution = restitution
edit-wall-restitution = wall restitution
edit-roughness = roughness
edit-wall-roughness = wall roughness
edit-friction = friction
edit-gravity = gravity
edit-edges = edges
edit-method = method
edit-broad-phase = broad phase
edit-substeps = substeps
edit-disc = edit a disc
edit-delete = delete
edit-launch = launch
edit-add-disc = a new disc
edit-fling = fling
edit-aim = set a velocity
no-room = No room for a new disc here

## Settings changed by a key
law-restitution = Restitution e
law-wall-restitution = Wall restitution
law-roughness = Roughness β
law-wall-roughness = Wall roughness β
time-scale = Time scale ×{ $scale }
gravity-now = Gravity { $gravity }
method-now = Method: { $method }
broad-phase-now = Broad phase: { $broad }
substeps-now = Substeps: { $substeps }
new-disc-radius = New discs: radius { $radius }
new-disc-mass = New discs: mass { $mass }
palette-safe = Discs in colour-blind-safe palette (Okabe-Ito, by disc number)
palette-scene = Discs in the scene's colours
text-size = Text size ×{ $scale }
com-view-off = Centre-of-mass view off: velocities as seen from the box
com-view-on = Centre-of-mass view: moving with the centre of mass at { $velocity }; Z again to leave

## Time: next collision, rewind, export
separated = The exact method needs discs apart: it separated { $pairs ->
    [one] 1 overlapping pair
   *[other] { $pairs } overlapping pairs
} of discs
separated-raised = The exact method needs discs apart: it separated { $pairs ->
    [one] 1 overlapping pair
   *[other] { $pairs } overlapping pairs
} of discs, which raised the energy by { $energy }
separated-lowered = The exact method needs discs apart: it separated { $pairs ->
    [one] 1 overlapping pair
   *[other] { $pairs } overlapping pairs
} of discs, which lowered the energy by { $energy }
next-collision-pair = Discs { $a } and { $b }, t = { $time }: { $momentum_kept ->
    [yes] total momentum unchanged
   *[no] total momentum changed by { $momentum }
}, { $energy_change ->
    [same] kinetic energy unchanged
    [less] kinetic energy { $energy } less
   *[more] kinetic energy { $energy } more
}
next-collision-wall = Disc { $disc } hit the { $wall ->
    [left] left
    [right] right
    [bottom] bottom
   *[top] top
} wall, t = { $time }: the wall pushed it with { $impulse }; { $energy_change ->
    [same] its kinetic energy unchanged
    [less] its kinetic energy { $energy } less
   *[more] its kinetic energy { $energy } more
}
next-collision-verlet = Discs collided at t = { $time }; verlet moves positions apart, so it has no before and after of one collision to show: the ledger has no row for it
stepped = { $steps ->
    [one] One step
   *[other] { $steps } steps
} of { $dt }: t = { $time }
next-collision-none = No collision within { $limit }
next-collision-at-once = { $impacts } impacts at the same moment, all listed in the Collisions tab. { $first }
rewound-to = Rewound to t = { $time } s (recorded: { $oldest } to { $newest } s); Space resumes from here
rewound-newest = At the newest recorded moment, t = { $time } s; Space runs on from here
nothing-recorded = Nothing recorded yet
exported-downloaded = Downloaded the totals, discs, collisions and wall impacts as CSV files
exported = Exported totals, discs, collisions and wall impacts to { $folder }/
not-exported = Not exported to { $folder }: { $error }
wall-name = { $wall ->
    [left] left wall
    [right] right wall
    [bottom] bottom wall
   *[top] top wall
}

## Editing a disc
edit-type-a-number = { $name }: type a number
edit-not-a-number = { $name }: “{ $text }” is not a number
edit-ambiguous-number = { $name }: “{ $text }” could be { $decimal } or { $grouped }; type the one you mean
edit-not-finite = { $name } must be a finite number
edit-speed-negative = The speed cannot be negative: type the opposite direction instead
edit-not-positive = { $name } must be more than 0
edit-radius-too-large = radius must be at most { $radius } m here
edit-out-of-range = { $name } must be between { $lo } and { $hi }
edit-too-fast = the speed must be at most 10⁸ m/s
slider-out-of-range = { $typed } is outside { $low } to { $high }: set to { $value }
slider-sign-dropped = { $typed } read as { $value }: the label gives the direction
edit-across-the-line = the discs here move along one line: { $name } must be 0
edit-nothing-changed = Nothing changed: type a new value first
edit-pending = Typed, not applied yet: Enter or Apply
edit-applied = Applied to disc { $disc }
edit-applied-table = Disc { $disc }: { $values }
edit-refused-table = Disc { $disc }: { $error }; nothing changed
edit-mass-overlaps = at { $mass } kg the disc would be { $size } m in radius (size follows mass) and overlap disc { $disc }
edit-mass-crosses-wall = at { $mass } kg the disc would be { $size } m in radius (size follows mass) and cross a wall
edit-position-off-the-line = the discs here move along one line: { $name } stays { $value } m
edit-position-crosses-wall = at { $at } the disc would cross a wall
edit-position-overlaps = at { $at } the disc would overlap disc { $disc }
edit-radius-crosses-wall = with a radius of { $radius } m the disc would cross a wall
edit-radius-overlaps = with a radius of { $radius } m the disc would overlap disc { $disc }

## Recovery
recovery-unreadable-moved = An unreadable recovery file was moved to { $file }: { $error }
recovery-unreadable-kept = An unreadable recovery file could not be moved: { $error }
autosave-failed = Autosave to { $place } failed: { $error }
browser-storage = the browser's storage
origin-recovered = recovered from { $file }
origin-kept = your last sandbox, kept by this browser
recovery-kept-in = Earlier session kept in { $file }
recovery-restored = Restored { $name }, paused where it was left: Space runs it
recovery-not-set-aside = Could not set the earlier session aside: { $error }
kept-not-set-aside = Could not keep your last sandbox aside: { $error }
recovery-question-browser = This browser kept your last sandbox, { $name } ({ $discs ->
    [one] 1 disc
   *[other] { $discs } discs
}). Restore it, or set it aside?
recovery-question = The last session ended with changes that were not saved. Restore its { $name } ({ $discs ->
    [one] 1 disc
   *[other] { $discs } discs
}), or set it aside?
sandbox-cannot-open = Cannot open the sandbox: { $error }
link-too-many-discs = { $discs } discs are too many for a link (at most { $most }): save the scene as a file instead
link-damaged = the link's scene is damaged ({ $error })
settings-unreadable = The settings in { $file } could not be read ({ $error }): the defaults hold
settings-not-saved = The settings were not saved to { $place }: { $error }
aimed = Disc { $disc }: velocity set to { $velocity }
aim-across-the-line = The discs here move along one line: { $keys } aim along it
key-left-right = Left and Right
key-up-down = Up and Down
dropped-file = dropped file
dropped-not-text = { $name }: not a text file
dropped-unreadable = { $name }: { $error }
dropped-empty = a dropped file without content
link-cannot-open = This link's scene cannot open: { $error }
origin-default = built-in default scene
origin-shared-link = the shared link
