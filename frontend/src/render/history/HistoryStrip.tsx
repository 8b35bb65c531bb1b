import { HISTORY_LIMIT } from './boundedHistory';
import type { HistoryEntry } from './RenderHistory';
import { formatFinished, formatSamples, recordName, recordTitle, type RenderRecord } from './renderRecord';
import './history.css';

/** Props of {@link HistoryStrip}. */
export interface HistoryStripProps {
  /** The element id, for the History button's `aria-controls`. */
  id: string;
  /** Newest first. */
  entries: readonly HistoryEntry[];
  /** The render the stage shows, if it is one of the list: Compare sets the others against it. */
  shownId: string | null;
  /** True for a render of the very scene in the editor (nothing to restore). */
  isCurrentScene: (record: RenderRecord) => boolean;
  onShow: (id: string) => void;
  onCompare: (id: string) => void;
  onRestore: (id: string) => void;
  /** The time the labels are written against (today's renders show only their time). */
  now?: number;
}

/**
 * The last renders, newest first, as a strip of thumbnails: a click shows one on the stage;
 * Compare sets one beside the render shown, with a slider; Restore scene puts its scene back in the
 * editor. Presentational: the panel owns the history.
 */
// eslint-disable-next-line react-hooks/purity -- the ages shown are as of this render, by design
export function HistoryStrip({ id, entries, shownId, isCurrentScene, onShow, onCompare, onRestore, now = Date.now() }: HistoryStripProps) {
  const shown = entries.find((e) => e.record.id === shownId) ?? null;
  return (
    <section id={id} className="render-history" aria-label="Render history">
      <p className="hint">
        {entries.length === 0
          ? 'No renders yet: each finished render appears here.'
          : `The last ${HISTORY_LIMIT} renders are kept in this browser, newest first.`}
      </p>
      {entries.length > 0 && (
        <ol className="render-history__list" aria-label="Renders">
          {entries.map(({ record, thumbnailUrl }) => {
            const title = recordTitle(record);
            const isShown = record.id === shownId;
            const current = isCurrentScene(record);
            return (
              <li key={record.id} className={isShown ? 'render-history__item is-shown' : 'render-history__item'}>
                <button type="button" className="render-history__show" aria-pressed={isShown} title={recordName(record, now)} onClick={() => onShow(record.id)}>
                  <img src={thumbnailUrl} alt="" draggable={false} />
                  <span className="render-history__title">
                    {title} <span className="render-history__name">{record.sceneName}</span>
                  </span>
                  <span className="render-history__meta">
                    {formatFinished(record.finishedAt, now)} · {record.width} × {record.height} · {formatSamples(record.samples, record.adaptive)}
                  </span>
                </button>
                <span className="render-history__actions">
                  <button
                    type="button"
                    className="small"
                    disabled={!shown || isShown}
                    aria-label={shown && !isShown ? `Compare ${title} with ${recordTitle(shown.record)}` : `Compare ${title}`}
                    title={shown && !isShown ? `Compare with ${recordTitle(shown.record)}, the render shown, with a slider` : 'Show another render first, then compare this one with it'}
                    onClick={() => onCompare(record.id)}
                  >
                    Compare
                  </button>
                  <button
                    type="button"
                    className="small"
                    disabled={current}
                    aria-label={`Restore scene of ${title}`}
                    title={current ? 'The editor holds this scene already' : "Replace the editor's scene by the one of this render (one undo step)"}
                    onClick={() => onRestore(record.id)}
                  >
                    Restore scene
                  </button>
                </span>
              </li>
            );
          })}
        </ol>
      )}
    </section>
  );
}
