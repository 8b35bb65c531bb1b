import { useRef } from 'react';
import { useAssetUrl } from '../hooks/useAssetUrl';
import { useImportFiles } from '../import/ImportContext';
import { withTextureField, withTextureType } from '../model/textureEdits';
import type { CheckerTexture, ImageTexture, Material, TextureType } from '../model/types';
import { ColorField } from './fields/ColorField';
import { NumberField } from './fields/NumberField';
import { SelectField } from './fields/SelectField';

/** Props of {@link InspectorTexture}. */
export interface InspectorTextureProps {
  /** JSON path of the material, e.g. `objects[2].material`. */
  path: string;
  /** The material (its texture, if any, is edited). */
  material: Material;
  /** Called with the whole new material after an edit. */
  onChange: (material: Material) => void;
}

const OPTIONS = [
  { value: 'none', label: 'None', hint: 'The material’s colour alone' },
  { value: 'checker', label: 'Checker', hint: 'Squares of two colours, a size in metres on the surface' },
  { value: 'image', label: 'Image', hint: 'A PNG or JPEG, uploaded once, which the colour multiplies' },
];

/**
 * A material's texture: none, a checker (two colours and the size of its squares) or an image
 * (a thumbnail, its repeats along u and v, and "Pick image…", which uploads a PNG or JPEG and puts
 * it on the selected object). Each change is one undo step; the fields are checked as the others.
 */
export function InspectorTexture({ path, material, onChange }: InspectorTextureProps) {
  const importFiles = useImportFiles();
  const picker = useRef<HTMLInputElement>(null);
  const texture = material.texture;
  const tpath = `${path}.texture`;
  const pick = () => picker.current?.click();
  const setType = (type: string) => {
    const next = withTextureType(material, type as TextureType | 'none');
    if (next) onChange(next);
    else pick();
  };
  return (
    <fieldset className="inspector-group" data-testid="texture">
      <legend>Texture</legend>
      <SelectField label="Texture" path={`${tpath}.type`} value={texture?.type ?? 'none'} options={OPTIONS} hint="What the colour multiplies" onCommit={setType} />
      {texture?.type === 'checker' && <CheckerFields path={tpath} texture={texture} onChange={(t) => onChange(withTextureField(material, () => t))} />}
      {texture?.type === 'image' && <ImageFields path={tpath} texture={texture} onChange={(t) => onChange(withTextureField(material, () => t))} />}
      {importFiles && (
        <>
          <button type="button" className="small" onClick={pick} title="Upload a PNG or JPEG and make it this object’s texture">
            Pick image…
          </button>
          <input
            ref={picker}
            className="visually-hidden"
            type="file"
            accept=".png,.jpg,.jpeg"
            tabIndex={-1}
            aria-hidden="true"
            data-testid="pick-texture"
            onChange={(event) => {
              const files = [...(event.currentTarget.files ?? [])];
              event.currentTarget.value = '';
              if (files.length > 0) importFiles(files.slice(0, 1));
            }}
          />
        </>
      )}
    </fieldset>
  );
}

function CheckerFields({ path, texture, onChange }: { path: string; texture: CheckerTexture; onChange: (t: CheckerTexture) => void }) {
  const color = (i: 0 | 1) => (
    <ColorField
      label={`Checker colour ${i + 1}`}
      path={`${path}.colors[${i}]`}
      value={texture.colors[i]}
      hint={`The ${i === 0 ? 'first' : 'second'} colour of the squares (sRGB)`}
      onCommit={(c) => onChange({ ...texture, colors: (i === 0 ? [c, texture.colors[1]] : [texture.colors[0], c]) as [string, string] })}
    />
  );
  return (
    <>
      {color(0)}
      {color(1)}
      <NumberField label="Square size" path={`${path}.size`} value={texture.size ?? 1} min={0} minExclusive step={0.1} hint="The side of a square, in metres on the surface (greater than 0)" onCommit={(size) => onChange({ ...texture, size })} />
    </>
  );
}

function ImageFields({ path, texture, onChange }: { path: string; texture: ImageTexture; onChange: (t: ImageTexture) => void }) {
  const { url, error } = useAssetUrl(texture.asset);
  const [su, sv] = texture.scale ?? [1, 1];
  return (
    <>
      {url && <img className="texture-thumbnail" src={url} alt={`Texture ${(texture.asset ?? texture.file ?? '').slice(0, 15)}…`} width={96} height={96} />}
      {error && (
        <p className="field-error" role="alert">
          Cannot show the image: {error}
        </p>
      )}
      <NumberField label="Repeat u" path={`${path}.scale[0]`} value={su} min={0} minExclusive step={0.5} hint="How many times the image repeats along u (greater than 0)" onCommit={(v) => onChange({ ...texture, scale: [v, sv] })} />
      <NumberField label="Repeat v" path={`${path}.scale[1]`} value={sv} min={0} minExclusive step={0.5} hint="How many times the image repeats along v (greater than 0)" onCommit={(v) => onChange({ ...texture, scale: [su, v] })} />
    </>
  );
}
