// ГОСТ 20999-83 table 4 (G, groups), table 5 (G meanings), tables 7-8 (M). Codes the standard
// leaves "not defined" or "permanently not defined" are absent. G90/G91 are group j: ISO 6983 and
// the standard's scan (ocr-a, where the letter is legible) agree; the other scan lost it.
#include "tape/functions.hpp"

namespace tape {
namespace {

constexpr Scope M = Scope::modal, B = Scope::one_block, U = Scope::unstated;

constexpr NcFunction functions[] = {
    {'G', 0, 'a', M, "Быстрое позиционирование", "rapid positioning"},
    {'G', 1, 'a', M, "Линейная интерполяция", "linear interpolation"},
    {'G', 2, 'a', M, "Круговая интерполяция, движение по часовой стрелке", "circular interpolation, clockwise"},
    {'G', 3, 'a', M, "Круговая интерполяция, движение против часовой стрелки",
     "circular interpolation, counter-clockwise"},
    {'G', 4, 0, U, "Пауза", "dwell"},
    {'G', 6, 'a', M, "Параболическая интерполяция", "parabolic interpolation"},
    {'G', 8, 0, B, "Разгон", "acceleration"},
    {'G', 9, 0, B, "Торможение", "deceleration"},
    {'G', 17, 'c', M, "Выбор плоскости XY", "XY plane selection"},
    {'G', 18, 'c', M, "Выбор плоскости ZX", "ZX plane selection"},
    {'G', 19, 'c', M, "Выбор плоскости YZ", "YZ plane selection"},
    {'G', 33, 'a', M, "Нарезание резьбы", "thread cutting, constant lead"},
    {'G', 34, 'a', M, "Нарезание резьбы с увеличивающимся шагом", "thread cutting, increasing lead"},
    {'G', 35, 'a', M, "Нарезание резьбы с уменьшающимся шагом", "thread cutting, decreasing lead"},
    {'G', 40, 0, U, "Отмена коррекции инструмента", "tool compensation cancel"},
    {'G', 41, 0, U, "Коррекция на фрезу — левая", "cutter compensation, left"},
    {'G', 42, 0, U, "Коррекция на фрезу — правая", "cutter compensation, right"},
    {'G', 43, 0, U, "Коррекция на положение инструмента — положительная", "tool offset, positive"},
    {'G', 44, 0, U, "Коррекция на положение инструмента — отрицательная", "tool offset, negative"},
    {'G', 53, 'f', M, "Отмена заданного смещения", "datum shift cancel"},
    {'G', 54, 'f', M, "Заданное смещение 1", "datum shift 1"},
    {'G', 55, 'f', M, "Заданное смещение 2", "datum shift 2"},
    {'G', 56, 'f', M, "Заданное смещение 3", "datum shift 3"},
    {'G', 57, 'f', M, "Заданное смещение 4", "datum shift 4"},
    {'G', 58, 'f', M, "Заданное смещение 5", "datum shift 5"},
    {'G', 59, 'f', M, "Заданное смещение 6", "datum shift 6"},
    {'G', 63, 0, B, "Нарезание резьбы метчиком", "tapping"},
    {'G', 80, 'e', M, "Отмена постоянного цикла", "fixed cycle cancel"},
    {'G', 81, 'e', M, "Постоянный цикл 1: сверление, зацентровка", "fixed cycle 1: drilling, spot drilling"},
    {'G', 82, 'e', M, "Постоянный цикл 2: сверление, зенкование", "fixed cycle 2: drilling with dwell, counterboring"},
    {'G', 83, 'e', M, "Постоянный цикл 3: глубокое сверление", "fixed cycle 3: deep hole drilling"},
    {'G', 84, 'e', M, "Постоянный цикл 4: нарезание резьбы метчиком", "fixed cycle 4: tapping"},
    {'G', 85, 'e', M, "Постоянный цикл 5: растачивание, развертывание", "fixed cycle 5: boring, reaming"},
    {'G', 86, 'e', M, "Постоянный цикл 6: растачивание", "fixed cycle 6: boring, spindle stop"},
    {'G', 87, 'e', M, "Постоянный цикл 7: растачивание", "fixed cycle 7: boring, manual retraction"},
    {'G', 88, 'e', M, "Постоянный цикл 8: растачивание", "fixed cycle 8: boring with dwell, manual retraction"},
    {'G', 89, 'e', M, "Постоянный цикл 9: растачивание, развертывание", "fixed cycle 9: boring with dwell, feed out"},
    {'G', 90, 'j', M, "Абсолютный размер", "absolute dimensions"},
    {'G', 91, 'j', M, "Размер в приращениях", "incremental dimensions"},
    {'G', 92, 0, B, "Установка абсолютных накопителей положения", "preload of position registers"},
    {'G', 93, 'k', M, "Скорость подачи в функции, обратной времени", "inverse time feed rate"},
    {'G', 94, 'k', M, "Подача в минуту", "feed per minute"},
    {'G', 95, 'k', M, "Подача на оборот", "feed per revolution"},
    {'G', 96, 'l', M, "Постоянная скорость резания", "constant cutting speed"},
    {'G', 97, 'l', M, "Обороты в минуту", "revolutions per minute"},
    {'M', 0, 0, B, "Программируемый останов", "program stop"},
    {'M', 1, 0, B, "Останов с подтверждением", "optional stop"},
    {'M', 2, 0, B, "Конец программы", "end of program"},
    {'M', 3, 0, M, "Вращение шпинделя по часовой стрелке", "spindle clockwise"},
    {'M', 4, 0, M, "Вращение шпинделя против часовой стрелки", "spindle counter-clockwise"},
    {'M', 5, 0, M, "Останов шпинделя", "spindle stop"},
    {'M', 6, 0, B, "Смена инструмента", "tool change"},
    {'M', 7, 0, M, "Включение охлаждения № 2", "coolant no. 2 on"},
    {'M', 8, 0, M, "Включение охлаждения № 1", "coolant no. 1 on"},
    {'M', 9, 0, M, "Отключение охлаждения", "coolant off"},
    {'M', 10, 0, M, "Зажим", "clamp"},
    {'M', 11, 0, M, "Разжим", "unclamp"},
    {'M', 19, 0, M, "Останов шпинделя в заданной позиции", "oriented spindle stop"},
    {'M', 30, 0, B, "Конец информации", "end of information (end of tape)"},
    {'M', 48, 0, M, "Отмена M49", "cancel M49"},
    {'M', 49, 0, M, "Отмена ручной коррекции", "manual override cancel"},
    {'M', 58, 0, M, "Отмена M59", "cancel M59"},
    {'M', 59, 0, M, "Постоянная скорость шпинделя", "constant spindle speed"},
};

}  // namespace

std::span<const NcFunction> nc_functions() { return functions; }

const NcFunction* find_nc_function(char address, long long code) {
    for (const auto& f : functions)
        if (f.address == address && f.code == code) return &f;
    return nullptr;
}

}  // namespace tape
