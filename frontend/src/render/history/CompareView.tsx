import { useId, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { compareFrame, containRect, dividerX, positionAfterKey, positionAt, START_POSITION } from './compareMath';
import './history.css';

/** One side of a comparison. */
export interface CompareSide {
  url: string;
  /** The image's size in pixels. */
  width: number;
  height: number;
  /** Which render it is, e.g. "Render 2 · 14:03:12 · up to 16 spp". */
  label: string;
}

/** Props of {@link CompareView}. */
export interface CompareViewProps {
  /** Shown left of the divider (the older render). */
  left: CompareSide;
  /** Shown right of the divider. */
  right: CompareSide;
  onClose: () => void;
}

/**
 * Two renders over each other in one frame, each fitted whole the same way (two renders of one
 * size cover the same pixels), `left` left of a vertical divider and `right` right of it. The
 * divider follows a drag anywhere on the frame, and is a slider for the keyboard: arrows, Page
 * Up/Down, Home, End. An SVG whose viewBox is the frame fits it to the stage, so no size is measured.
 */
export function CompareView({ left, right, onClose }: CompareViewProps) {
  const [position, setPosition] = useState(START_POSITION);
  const frameRef = useRef<SVGRectElement>(null);
  const dragging = useRef(false);
  const clipId = `compare-clip-${useId().replace(/[^a-zA-Z0-9_-]/g, '')}`;
  const frame = compareFrame(left, right);
  const x = dividerX(position, frame);
  const a = containRect(left, frame);
  const b = containRect(right, frame);

  const follow = (e: PointerEvent) => {
    const box = frameRef.current?.getBoundingClientRect();
    if (box) setPosition(positionAt(e.clientX, box.left, box.width));
  };
  const onPointerDown = (e: PointerEvent<SVGSVGElement>) => {
    dragging.current = true;
    e.currentTarget.setPointerCapture?.(e.pointerId);
    follow(e);
  };
  const onKeyDown = (e: KeyboardEvent) => {
    const next = positionAfterKey(position, e.key, e.shiftKey);
    if (next === null) return;
    e.preventDefault();
    setPosition(next);
  };
  const handle = Math.max(frame.width, frame.height) * 0.025;
  return (
    <figure className="compare-view" data-testid="compare-view">
      <figcaption className="compare-view__labels">
        <span data-testid="compare-left">◀ {left.label}</span>
        <button type="button" className="small" onClick={onClose}>
          End comparison
        </button>
        <span data-testid="compare-right">{right.label} ▶</span>
      </figcaption>
      <div className="render-frame compare-view__frame">
        <svg
          viewBox={`0 0 ${frame.width} ${frame.height}`}
          preserveAspectRatio="xMidYMid meet"
          className="compare-view__svg"
          onPointerDown={onPointerDown}
          onPointerMove={(e) => dragging.current && follow(e)}
          onPointerUp={() => (dragging.current = false)}
          onPointerCancel={() => (dragging.current = false)}
        >
          <defs>
            <clipPath id={clipId}>
              <rect x={x} y={0} width={frame.width - x} height={frame.height} />
            </clipPath>
          </defs>
          <rect ref={frameRef} width={frame.width} height={frame.height} fill="none" />
          <image href={left.url} x={a.x} y={a.y} width={a.width} height={a.height} preserveAspectRatio="none" data-testid="compare-image-left" aria-label={`${left.label}, left`} role="img" />
          <image href={right.url} x={b.x} y={b.y} width={b.width} height={b.height} preserveAspectRatio="none" clipPath={`url(#${clipId})`} data-testid="compare-image-right" aria-label={`${right.label}, right`} role="img" />
          <line x1={x} x2={x} y1={0} y2={frame.height} className="compare-view__divider" vectorEffect="non-scaling-stroke" />
          <g
            role="slider"
            tabIndex={0}
            className="compare-view__handle"
            aria-label="Divider between the two renders"
            aria-orientation="horizontal"
            aria-valuemin={0}
            aria-valuemax={100}
            aria-valuenow={position}
            aria-valuetext={`${position}%: ${left.label} on the left, ${right.label} on the right`}
            onKeyDown={onKeyDown}
          >
            <circle cx={x} cy={frame.height / 2} r={handle} />
          </g>
        </svg>
      </div>
    </figure>
  );
}
