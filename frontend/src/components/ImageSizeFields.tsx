import { useState } from 'react';
import { presetIndex, resize, SIZE_PRESETS, type ImageSize } from '../model/imageSize';
import { NumberField } from './fields/NumberField';

/** Props of {@link ImageSizeFields}. */
export interface ImageSizeFieldsProps {
  size: ImageSize;
  /** Called once per change with the whole new size (one undo step). */
  onCommit: (size: ImageSize) => void;
}

/** The image's size: a preset menu, width and height, and a lock that keeps the aspect ratio. */
export function ImageSizeFields({ size, onCommit }: ImageSizeFieldsProps) {
  const [locked, setLocked] = useState(false);
  const preset = presetIndex(size);
  return (
    <>
      <div className="field">
        <label htmlFor="image-size-preset">Size preset</label>
        <select
          id="image-size-preset"
          value={preset}
          onChange={(event) => {
            const picked = SIZE_PRESETS[Number(event.target.value)];
            if (picked) onCommit({ ...picked.size });
          }}
        >
          <option value={-1} disabled>
            Custom ({size.width} × {size.height})
          </option>
          {SIZE_PRESETS.map((p, i) => (
            <option key={p.label} value={i}>
              {p.label}
            </option>
          ))}
        </select>
      </div>
      <NumberField label="Width (px)" path="image.width" value={size.width} integer min={1} max={4096} step={1} onCommit={(width) => onCommit(resize(size, 'width', width, locked))} />
      <NumberField label="Height (px)" path="image.height" value={size.height} integer min={1} max={4096} step={1} onCommit={(height) => onCommit(resize(size, 'height', height, locked))} />
      <div className="field field--checkbox" title="Changing one side changes the other, keeping the width : height ratio">
        <input id="image-aspect-lock" type="checkbox" checked={locked} onChange={(event) => setLocked(event.target.checked)} />
        <label htmlFor="image-aspect-lock">Lock aspect ratio ({(size.width / size.height).toFixed(3)})</label>
      </div>
    </>
  );
}
