import { useImportStore } from '../import/importStore';

const PHASES = { hashing: 'hashing', reading: 'reading', uploading: 'uploading' } as const;

/** The import under way (file, phase, a progress bar) or what the last one did; nothing otherwise. */
export function ImportProgress() {
  const { current, waiting, done } = useImportStore();
  if (current) {
    const percent = Math.round(100 * current.fraction);
    return (
      <div className="import-progress" role="status" data-testid="import-progress">
        <span>
          Importing {current.name}: {PHASES[current.phase]} {percent}%{waiting > 0 ? ` (${waiting} more waiting)` : ''}
        </span>
        <progress max={100} value={percent} aria-label={`Import of ${current.name}`} />
      </div>
    );
  }
  if (!done) return null;
  return (
    <div className="import-progress" role="status" data-testid="import-progress">
      <span>{done}</span>
      <button type="button" className="small" onClick={() => useImportStore.setState({ done: null })}>
        Dismiss
      </button>
    </div>
  );
}
