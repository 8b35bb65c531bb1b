/** How the render panel writes times, rates and fractions. Pure functions. */

/** 850 → "850 ms", 12345 → "12.3 s", 125000 → "2 min 05 s". */
export function formatMillis(millis: number): string {
  if (millis < 1000) return `${Math.max(0, Math.round(millis))} ms`;
  if (millis < 60_000) return `${(millis / 1000).toFixed(1)} s`;
  const seconds = Math.round(millis / 1000);
  return `${Math.floor(seconds / 60)} min ${String(seconds % 60).padStart(2, '0')} s`;
}

/** 12_300_000 → "12.3 M rays/s". */
export function formatRate(raysPerSecond: number): string {
  const units: [number, string][] = [
    [1e9, 'G'],
    [1e6, 'M'],
    [1e3, 'k'],
  ];
  for (const [scale, prefix] of units) {
    if (raysPerSecond >= scale) return `${(raysPerSecond / scale).toFixed(1)} ${prefix} rays/s`;
  }
  return `${Math.round(raysPerSecond)} rays/s`;
}

/** A progress fraction as a whole percentage, 0..100; 0.999 stays 99 until the job is done. */
export function toPercent(fraction: number): number {
  if (!Number.isFinite(fraction)) return 0;
  return Math.min(100, Math.max(0, Math.floor(fraction * 100)));
}

/** 1 → "1 second", 90 → "90 seconds". */
export function formatSeconds(seconds: number): string {
  return seconds === 1 ? '1 second' : `${seconds} seconds`;
}
