import { TextField } from './TextField';

/** Props of {@link NameField}. */
export interface NameFieldProps {
  /** JSON path of the name, e.g. `objects[2].name`. */
  path: string;
  value: string | undefined;
  /** The trimmed name, or undefined for none (the field is then left out of the scene). */
  onCommit: (name: string | undefined) => void;
}

/** The optional name of an object or a light: the editor's, kept in the file, ignored by the renderer. */
export function NameField({ path, value, onCommit }: NameFieldProps) {
  return (
    <TextField
      label="Name"
      path={path}
      value={value ?? ''}
      maxLength={200}
      hint="Your name for it, kept in the file (the renderer ignores it); empty for none"
      onCommit={(name) => onCommit(name.trim() === '' ? undefined : name.trim())}
    />
  );
}
