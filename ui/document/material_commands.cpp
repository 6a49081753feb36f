#include "ui/document/material_commands.h"

#include "ui/document/editor_document.h"

namespace mq::ui {

SetMaterialCommand::SetMaterialCommand(EditorDocument* document, int index, Material after, const QString& what)
    : document_(document), index_(index), before_(document->character().materials.at(index)), after_(std::move(after)) {
  setText(QObject::tr("%1 of %2").arg(what, QString::fromStdString(after_.name)));
}

void SetMaterialCommand::undo() { document_->setMaterial(index_, before_); }
void SetMaterialCommand::redo() { document_->setMaterial(index_, after_); }

}  // namespace mq::ui
