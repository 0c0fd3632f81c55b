// Angles on the pages: the server streams radians (a signal whose unit is "rad" is an angle: its plug-in or the robot
// says so); the pages show degrees by default. One conversion, used by every page.

export type AngleUnit = 'deg' | 'rad';

export const degPerRad = 180 / Math.PI;

/** The factor that turns a value in <unit> into what the page shows when angles are shown in <angles>. */
export function displayFactor(unit: string, angles: AngleUnit): number {
  return unit === 'rad' && angles === 'deg' ? degPerRad : 1;
}

/** The unit a value in <unit> is shown in when angles are shown in <angles>. */
export function displayUnit(unit: string, angles: AngleUnit): string {
  return unit === 'rad' ? angles : unit;
}
