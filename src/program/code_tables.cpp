// The G and M code tables of the dialects. ГОСТ 20999-83 (tables 4 and 7) gives every two-digit G and
// M function a meaning or leaves it to the controller (note 1: "for individual use"), so its table is
// the range 00-99 and its names are tape/functions.hpp's. Fanuc's table is the union of the Series
// 0i/16i/18i/21i/30i lathe (G code system A, with B and C where they differ) and mill codes and of the
// Haas controls that follow Fanuc's format; its M codes beyond M00-M02, M30, M98, M99 are the machine
// builder's, so any M up to three digits is known. LinuxCNC's is its G-code and M-code reference
// (2.9), with M100-M199 the user's own codes. Codes a machine builder or a remap adds beyond these are
// the price of a table: they are reported, and the report says whose table it is.
#include "tape/code_tables.hpp"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <optional>
#include <span>

#include "tape/functions.hpp"
#include "tape/program.hpp"

namespace tape {
namespace {

constexpr Machine A = Machine::any, L = Machine::lathe, Mi = Machine::mill;

struct Code {
    char letter;
    std::string_view value;
    Machine machine;
    std::string_view en;
    std::string_view ru;
};

// Whole numbers from..to are known (and named, when en is not empty).
struct CodeRange {
    char letter;
    int from, to;
    std::string_view en;
    std::string_view ru;
};

constexpr Code fanuc_codes[] = {
    {'G', "0", A, "rapid positioning", "быстрое позиционирование"},
    {'G', "1", A, "linear interpolation", "линейная интерполяция"},
    {'G', "2", A, "circular interpolation, clockwise", "круговая интерполяция по часовой стрелке"},
    {'G', "3", A, "circular interpolation, counter-clockwise", "круговая интерполяция против часовой стрелки"},
    {'G', "2.2", Mi, "involute interpolation, clockwise", "эвольвентная интерполяция по часовой стрелке"},
    {'G', "3.2", Mi, "involute interpolation, counter-clockwise", "эвольвентная интерполяция против часовой стрелки"},
    {'G', "2.3", Mi, "exponential interpolation, clockwise", "экспоненциальная интерполяция по часовой стрелке"},
    {'G', "3.3", Mi, "exponential interpolation, counter-clockwise",
     "экспоненциальная интерполяция против часовой стрелки"},
    {'G', "2.4", Mi, "3-D circular interpolation", "трёхмерная круговая интерполяция"},
    {'G', "3.4", Mi, "3-D circular interpolation", "трёхмерная круговая интерполяция"},
    {'G', "4", A, "dwell", "пауза"},
    {'G', "5", A, "high-speed cycle machining", "высокоскоростная обработка по циклу"},
    {'G', "5.1", A, "AI contour control (Q1 on, Q0 off)", "AI-контурное управление (Q1 вкл., Q0 выкл.)"},
    {'G', "5.4", A, "HRV3 on/off", "HRV3 вкл./выкл."},
    {'G', "6.2", Mi, "NURBS interpolation", "NURBS-интерполяция"},
    {'G', "7", Mi, "hypothetical axis interpolation", "интерполяция с воображаемой осью"},
    {'G', "7.1", A, "cylindrical interpolation", "цилиндрическая интерполяция"},
    {'G', "8", A, "AI look-ahead control", "управление с опережающим просмотром"},
    {'G', "9", A, "exact stop", "точный останов"},
    {'G', "10", A, "programmable data input (offsets, work coordinates)",
     "программный ввод данных (коррекции, системы координат)"},
    {'G', "10.6", A, "tool retract and recover", "отвод и возврат инструмента"},
    {'G', "11", A, "programmable data input cancel", "отмена программного ввода данных"},
    {'G', "12", Mi, "circular pocket milling, clockwise (Haas)", "фрезерование круглого кармана по часовой (Haas)"},
    {'G', "12.1", A, "polar coordinate interpolation", "интерполяция в полярных координатах"},
    {'G', "13", Mi, "circular pocket milling, counter-clockwise (Haas)",
     "фрезерование круглого кармана против часовой (Haas)"},
    {'G', "13.1", A, "polar coordinate interpolation cancel", "отмена интерполяции в полярных координатах"},
    {'G', "15", Mi, "polar coordinate command cancel", "отмена задания в полярных координатах"},
    {'G', "16", Mi, "polar coordinate command", "задание в полярных координатах"},
    {'G', "17", A, "XY plane selection", "выбор плоскости XY"},
    {'G', "18", A, "ZX plane selection", "выбор плоскости ZX"},
    {'G', "19", A, "YZ plane selection", "выбор плоскости YZ"},
    {'G', "20", A, "input in inches", "ввод в дюймах"},
    {'G', "21", A, "input in millimetres", "ввод в миллиметрах"},
    {'G', "22", A, "stored stroke check on", "контроль запретной зоны вкл."},
    {'G', "23", A, "stored stroke check off", "контроль запретной зоны выкл."},
    {'G', "25", A, "spindle speed fluctuation detection off", "контроль колебаний скорости шпинделя выкл."},
    {'G', "26", A, "spindle speed fluctuation detection on", "контроль колебаний скорости шпинделя вкл."},
    {'G', "27", A, "reference position return check", "проверка возврата в референтную точку"},
    {'G', "28", A, "return to the reference position", "возврат в референтную точку"},
    {'G', "29", A, "return from the reference position", "возврат из референтной точки"},
    {'G', "30", A, "return to the 2nd, 3rd or 4th reference position", "возврат во 2-ю, 3-ю или 4-ю референтную точку"},
    {'G', "30.1", A, "floating reference position return", "возврат в плавающую референтную точку"},
    {'G', "31", A, "skip function (probing)", "функция пропуска (измерение)"},
    {'G', "32", L, "thread cutting", "нарезание резьбы"},
    {'G', "33", A, "thread cutting (mill; lathe G code systems B and C)",
     "нарезание резьбы (фрезерные; токарные, системы кодов B и C)"},
    {'G', "34", L, "variable lead thread cutting", "нарезание резьбы с переменным шагом"},
    {'G', "35", L, "circular thread cutting, clockwise", "нарезание резьбы по дуге по часовой стрелке"},
    {'G', "36", L, "circular thread cutting, counter-clockwise; automatic tool offset X",
     "нарезание резьбы по дуге против часовой стрелки; автоматическая коррекция по X"},
    {'G', "37", A, "automatic tool length measurement (mill); automatic tool offset Z (lathe)",
     "автоматическое измерение длины инструмента (фрезерные); автоматическая коррекция по Z (токарные)"},
    {'G', "37.1", L, "automatic tool offset X", "автоматическая коррекция по X"},
    {'G', "37.2", L, "automatic tool offset Z", "автоматическая коррекция по Z"},
    {'G', "38", Mi, "cutter compensation vector retention", "сохранение вектора коррекции на радиус"},
    {'G', "39", Mi, "corner circular interpolation", "круговая интерполяция на углу"},
    {'G', "40", A, "cutter or tool nose radius compensation cancel", "отмена коррекции на радиус инструмента"},
    {'G', "41", A, "cutter or tool nose radius compensation, left", "коррекция на радиус инструмента слева"},
    {'G', "42", A, "cutter or tool nose radius compensation, right", "коррекция на радиус инструмента справа"},
    {'G', "40.1", Mi, "normal direction control cancel", "отмена управления по нормали"},
    {'G', "41.1", Mi, "normal direction control, left", "управление по нормали слева"},
    {'G', "42.1", Mi, "normal direction control, right", "управление по нормали справа"},
    {'G', "41.2", Mi, "3-D cutter compensation, left", "трёхмерная коррекция на радиус слева"},
    {'G', "42.2", Mi, "3-D cutter compensation, right", "трёхмерная коррекция на радиус справа"},
    {'G', "43", A, "tool length compensation, plus", "коррекция на длину инструмента, плюс"},
    {'G', "44", Mi, "tool length compensation, minus", "коррекция на длину инструмента, минус"},
    {'G', "43.1", Mi, "tool length compensation in the tool axis", "коррекция на длину по оси инструмента"},
    {'G', "43.4", Mi, "tool centre point control, type 1", "управление центром инструмента, тип 1"},
    {'G', "43.5", Mi, "tool centre point control, type 2", "управление центром инструмента, тип 2"},
    {'G', "45", Mi, "tool offset increase", "увеличение на величину коррекции"},
    {'G', "46", Mi, "tool offset decrease", "уменьшение на величину коррекции"},
    {'G', "47", Mi, "tool offset double increase (Haas: text engraving)",
     "удвоенное увеличение на величину коррекции (Haas: гравировка текста)"},
    {'G', "48", Mi, "tool offset double decrease", "удвоенное уменьшение на величину коррекции"},
    {'G', "49", A, "tool length compensation cancel", "отмена коррекции на длину инструмента"},
    {'G', "49.1", Mi, "tool length compensation in the tool axis cancel",
     "отмена коррекции на длину по оси инструмента"},
    {'G', "50", L, "coordinate system setting, maximum spindle speed", "установка системы координат, предел оборотов"},
    {'G', "50", Mi, "scaling cancel", "отмена масштабирования"},
    {'G', "51", Mi, "scaling", "масштабирование"},
    {'G', "50.1", A, "programmable mirror image cancel", "отмена программного зеркального отображения"},
    {'G', "51.1", A, "programmable mirror image", "программное зеркальное отображение"},
    {'G', "50.2", L, "polygon turning cancel", "отмена многогранного точения"},
    {'G', "51.2", L, "polygon turning", "многогранное точение"},
    {'G', "50.3", L, "workpiece coordinate system preset", "предустановка системы координат детали"},
    {'G', "52", A, "local coordinate system", "локальная система координат"},
    {'G', "53", A, "machine coordinate system", "система координат станка"},
    {'G', "53.1", Mi, "tool axis direction control", "управление направлением оси инструмента"},
    {'G', "54", A, "workpiece coordinate system 1", "система координат детали 1"},
    {'G', "55", A, "workpiece coordinate system 2", "система координат детали 2"},
    {'G', "56", A, "workpiece coordinate system 3", "система координат детали 3"},
    {'G', "57", A, "workpiece coordinate system 4", "система координат детали 4"},
    {'G', "58", A, "workpiece coordinate system 5", "система координат детали 5"},
    {'G', "59", A, "workpiece coordinate system 6", "система координат детали 6"},
    {'G', "54.1", A, "additional workpiece coordinate systems (P)", "дополнительные системы координат детали (P)"},
    {'G', "54.2", Mi, "rotary table dynamic fixture offset", "динамическое смещение поворотного стола"},
    {'G', "60", Mi, "single direction positioning", "позиционирование с одного направления"},
    {'G', "61", A, "exact stop mode", "режим точного останова"},
    {'G', "62", Mi, "automatic corner override", "автоматическая коррекция подачи на углах"},
    {'G', "63", A, "tapping mode", "режим нарезания резьбы метчиком"},
    {'G', "64", A, "cutting mode", "режим резания"},
    {'G', "65", A, "macro call", "вызов макропрограммы"},
    {'G', "66", A, "macro modal call", "модальный вызов макропрограммы"},
    {'G', "66.1", A, "macro modal call, each block", "модальный вызов макропрограммы в каждом кадре"},
    {'G', "67", A, "macro modal call cancel", "отмена модального вызова макропрограммы"},
    {'G', "68", Mi, "coordinate system rotation", "поворот системы координат"},
    {'G', "68", L, "mirror image for double turrets", "зеркальное отображение для двух револьверных головок"},
    {'G', "68.2", Mi, "tilted working plane", "наклонная рабочая плоскость"},
    {'G', "69", Mi, "coordinate system rotation cancel", "отмена поворота системы координат"},
    {'G', "69", L, "mirror image for double turrets cancel", "отмена зеркального отображения для двух головок"},
    {'G', "70", L, "finishing cycle", "цикл чистовой обработки"},
    {'G', "70", Mi, "bolt hole circle (Haas)", "отверстия по окружности (Haas)"},
    {'G', "71", L, "stock removal in turning", "цикл черновой продольной обработки"},
    {'G', "71", Mi, "bolt hole arc (Haas)", "отверстия по дуге (Haas)"},
    {'G', "72", L, "stock removal in facing", "цикл черновой торцевой обработки"},
    {'G', "72", Mi, "bolt holes along an angle (Haas)", "отверстия по прямой под углом (Haas)"},
    {'G', "72.1", Mi, "figure copying, rotation", "копирование контура с поворотом"},
    {'G', "72.2", Mi, "figure copying, parallel shift", "копирование контура со сдвигом"},
    {'G', "73", L, "pattern repeating cycle", "цикл повторения контура"},
    {'G', "73", Mi, "high-speed peck drilling cycle", "цикл высокоскоростного прерывистого сверления"},
    {'G', "74", L, "end face peck drilling cycle", "цикл торцевого прерывистого сверления"},
    {'G', "74", Mi, "left-hand tapping cycle", "цикл нарезания левой резьбы метчиком"},
    {'G', "75", L, "outer or inner diameter grooving cycle", "цикл прорезки канавок"},
    {'G', "76", L, "multiple threading cycle", "многопроходный цикл нарезания резьбы"},
    {'G', "76", Mi, "fine boring cycle", "цикл чистового растачивания"},
    {'G', "77", L, "outer or inner diameter cutting cycle (G code systems B and C)",
     "цикл продольного точения (системы кодов B и C)"},
    {'G', "78", L, "threading cycle (G code systems B and C)", "цикл нарезания резьбы (системы кодов B и C)"},
    {'G', "79", L, "end face turning cycle (G code systems B and C)", "цикл торцевого точения (системы кодов B и C)"},
    {'G', "80", A, "canned cycle cancel", "отмена постоянного цикла"},
    {'G', "81", A, "drilling cycle", "цикл сверления"},
    {'G', "82", A, "drilling cycle with dwell", "цикл сверления с паузой"},
    {'G', "83", A, "peck drilling cycle", "цикл прерывистого сверления"},
    {'G', "84", A, "tapping cycle", "цикл нарезания резьбы метчиком"},
    {'G', "84.2", A, "rigid tapping cycle", "цикл жёсткого нарезания резьбы"},
    {'G', "84.3", Mi, "rigid left-hand tapping cycle", "цикл жёсткого нарезания левой резьбы"},
    {'G', "85", A, "boring cycle", "цикл растачивания"},
    {'G', "86", A, "boring cycle, spindle stop", "цикл растачивания с остановом шпинделя"},
    {'G', "87", Mi, "back boring cycle", "цикл обратного растачивания"},
    {'G', "87", L, "side drilling cycle", "цикл бокового сверления"},
    {'G', "88", Mi, "boring cycle, manual retraction", "цикл растачивания с ручным отводом"},
    {'G', "88", L, "side tapping cycle", "цикл бокового нарезания резьбы"},
    {'G', "89", Mi, "boring cycle with dwell", "цикл растачивания с паузой"},
    {'G', "89", L, "side boring cycle", "цикл бокового растачивания"},
    {'G', "90", Mi, "absolute dimensions", "абсолютный размер"},
    {'G', "90", L, "outer or inner diameter cutting cycle (G code system A)",
     "цикл продольного точения (система кодов A)"},
    {'G', "91", A, "incremental dimensions", "размер в приращениях"},
    {'G', "92", Mi, "coordinate system setting", "установка системы координат"},
    {'G', "92", L, "threading cycle (G code system A)", "цикл нарезания резьбы (система кодов A)"},
    {'G', "92.1", A, "workpiece coordinate system preset", "предустановка системы координат детали"},
    {'G', "93", Mi, "inverse time feed", "подача в функции, обратной времени"},
    {'G', "94", Mi, "feed per minute", "подача в минуту"},
    {'G', "94", L, "end face turning cycle (G code system A)", "цикл торцевого точения (система кодов A)"},
    {'G', "95", Mi, "feed per revolution", "подача на оборот"},
    {'G', "96", A, "constant surface speed", "постоянная скорость резания"},
    {'G', "97", A, "constant surface speed cancel", "отмена постоянной скорости резания"},
    {'G', "98", Mi, "canned cycle: return to the initial level", "постоянный цикл: отвод на исходный уровень"},
    {'G', "98", L, "feed per minute (G code system A)", "подача в минуту (система кодов A)"},
    {'G', "99", Mi, "canned cycle: return to the R level", "постоянный цикл: отвод на уровень R"},
    {'G', "99", L, "feed per revolution (G code system A)", "подача на оборот (система кодов A)"},
    {'G', "100", Mi, "mirror image cancel (Haas)", "отмена зеркального отображения (Haas)"},
    {'G', "101", Mi, "mirror image (Haas)", "зеркальное отображение (Haas)"},
    {'G', "103", Mi, "limit block look-ahead (Haas)", "ограничение просмотра кадров (Haas)"},
    {'G', "107", A, "cylindrical interpolation", "цилиндрическая интерполяция"},
    {'G', "112", A, "polar coordinate interpolation", "интерполяция в полярных координатах"},
    {'G', "113", A, "polar coordinate interpolation cancel", "отмена интерполяции в полярных координатах"},
    {'G', "136", Mi, "automatic work offset centre measurement (Haas)",
     "автоматическое измерение центра детали (Haas)"},
    {'G', "141", Mi, "3-D cutter compensation (Haas)", "трёхмерная коррекция на радиус (Haas)"},
    {'G', "143", Mi, "5-axis tool length compensation (Haas)", "пятиосевая коррекция на длину (Haas)"},
    {'G', "150", Mi, "general purpose pocket milling (Haas)", "фрезерование кармана общего вида (Haas)"},
    {'G', "153", Mi, "5-axis high-speed peck drilling (Haas)", "пятиосевое высокоскоростное сверление (Haas)"},
    {'G', "154", Mi, "work coordinates P1-P99 (Haas)", "системы координат детали P1-P99 (Haas)"},
    {'G', "174", Mi, "counter-clockwise non-vertical rigid tapping (Haas)",
     "жёсткое нарезание резьбы не по вертикали, против часовой (Haas)"},
    {'G', "184", Mi, "reverse tapping cycle (Haas)", "цикл нарезания левой резьбы (Haas)"},
    {'G', "187", Mi, "smoothness level (Haas)", "уровень сглаживания (Haas)"},
    {'G', "234", Mi, "tool centre point control (Haas)", "управление центром инструмента (Haas)"},
    {'G', "254", Mi, "dynamic work offset (Haas)", "динамическое смещение детали (Haas)"},
    {'G', "255", Mi, "dynamic work offset cancel (Haas)", "отмена динамического смещения детали (Haas)"},
    {'M', "0", A, "program stop", "программируемый останов"},
    {'M', "1", A, "optional stop", "останов с подтверждением"},
    {'M', "2", A, "end of program", "конец программы"},
    {'M', "3", A, "spindle clockwise", "вращение шпинделя по часовой стрелке"},
    {'M', "4", A, "spindle counter-clockwise", "вращение шпинделя против часовой стрелки"},
    {'M', "5", A, "spindle stop", "останов шпинделя"},
    {'M', "6", A, "tool change", "смена инструмента"},
    {'M', "8", A, "coolant on", "включение охлаждения"},
    {'M', "9", A, "coolant off", "отключение охлаждения"},
    {'M', "19", A, "spindle orientation", "ориентация шпинделя"},
    {'M', "29", A, "rigid tapping mode", "режим жёсткого нарезания резьбы"},
    {'M', "30", A, "end of program, rewind", "конец программы с возвратом к началу"},
    {'M', "97", A, "local subprogram call (Haas)", "вызов локальной подпрограммы (Haas)"},
    {'M', "98", A, "subprogram call", "вызов подпрограммы"},
    {'M', "99", A, "end of subprogram", "конец подпрограммы"},
    {'M', "198", A, "subprogram call from external memory", "вызов подпрограммы из внешней памяти"},
};

constexpr CodeRange fanuc_ranges[] = {
    {'G', 110, 129, "additional work coordinates (Haas)", "дополнительные системы координат детали (Haas)"},
    {'M', 0, 999, "", ""},  // the machine builder's M codes
};

constexpr Code linuxcnc_codes[] = {
    {'G', "0", A, "rapid move", "быстрое перемещение"},
    {'G', "1", A, "linear move", "линейное перемещение"},
    {'G', "2", A, "arc or helix, clockwise", "дуга или винтовая линия по часовой стрелке"},
    {'G', "3", A, "arc or helix, counter-clockwise", "дуга или винтовая линия против часовой стрелки"},
    {'G', "4", A, "dwell", "пауза"},
    {'G', "5", A, "cubic spline", "кубический сплайн"},
    {'G', "5.1", A, "quadratic B-spline", "квадратичный B-сплайн"},
    {'G', "5.2", A, "NURBS block", "NURBS-кадр"},
    {'G', "5.3", A, "NURBS block end", "конец NURBS-кадра"},
    {'G', "7", L, "lathe diameter mode", "режим диаметра (токарные)"},
    {'G', "8", L, "lathe radius mode", "режим радиуса (токарные)"},
    {'G', "10", A, "set tool table or coordinate system (L)", "запись таблицы инструментов или системы координат (L)"},
    {'G', "17", A, "XY plane", "плоскость XY"},
    {'G', "18", A, "ZX plane", "плоскость ZX"},
    {'G', "19", A, "YZ plane", "плоскость YZ"},
    {'G', "17.1", A, "UV plane", "плоскость UV"},
    {'G', "18.1", A, "WU plane", "плоскость WU"},
    {'G', "19.1", A, "VW plane", "плоскость VW"},
    {'G', "20", A, "units: inches", "единицы: дюймы"},
    {'G', "21", A, "units: millimetres", "единицы: миллиметры"},
    {'G', "28", A, "go to the stored position 1", "переход в запомненную позицию 1"},
    {'G', "28.1", A, "store position 1", "запомнить позицию 1"},
    {'G', "30", A, "go to the stored position 2", "переход в запомненную позицию 2"},
    {'G', "30.1", A, "store position 2", "запомнить позицию 2"},
    {'G', "33", A, "spindle-synchronised motion", "перемещение, синхронное со шпинделем"},
    {'G', "33.1", A, "rigid tapping", "жёсткое нарезание резьбы"},
    {'G', "38.2", A, "probe toward the workpiece, error if no contact", "щуп к детали, ошибка без касания"},
    {'G', "38.3", A, "probe toward the workpiece", "щуп к детали"},
    {'G', "38.4", A, "probe away from the workpiece, error if no loss of contact",
     "щуп от детали, ошибка без потери касания"},
    {'G', "38.5", A, "probe away from the workpiece", "щуп от детали"},
    {'G', "40", A, "cutter compensation off", "коррекция на радиус выкл."},
    {'G', "41", A, "cutter compensation, left", "коррекция на радиус слева"},
    {'G', "42", A, "cutter compensation, right", "коррекция на радиус справа"},
    {'G', "41.1", A, "dynamic cutter compensation, left", "динамическая коррекция на радиус слева"},
    {'G', "42.1", A, "dynamic cutter compensation, right", "динамическая коррекция на радиус справа"},
    {'G', "43", A, "tool length offset", "коррекция на длину инструмента"},
    {'G', "43.1", A, "dynamic tool length offset", "динамическая коррекция на длину"},
    {'G', "43.2", A, "additional tool length offset", "дополнительная коррекция на длину"},
    {'G', "49", A, "tool length offset cancel", "отмена коррекции на длину"},
    {'G', "52", A, "local coordinate system offset", "смещение локальной системы координат"},
    {'G', "53", A, "move in machine coordinates", "перемещение в координатах станка"},
    {'G', "54", A, "coordinate system 1", "система координат 1"},
    {'G', "55", A, "coordinate system 2", "система координат 2"},
    {'G', "56", A, "coordinate system 3", "система координат 3"},
    {'G', "57", A, "coordinate system 4", "система координат 4"},
    {'G', "58", A, "coordinate system 5", "система координат 5"},
    {'G', "59", A, "coordinate system 6", "система координат 6"},
    {'G', "59.1", A, "coordinate system 7", "система координат 7"},
    {'G', "59.2", A, "coordinate system 8", "система координат 8"},
    {'G', "59.3", A, "coordinate system 9", "система координат 9"},
    {'G', "61", A, "exact path mode", "режим точного пути"},
    {'G', "61.1", A, "exact stop mode", "режим точного останова"},
    {'G', "64", A, "path blending (P tolerance, Q naive CAM tolerance)", "сглаживание пути (допуски P, Q)"},
    {'G', "70", L, "lathe finishing cycle", "токарный цикл чистовой обработки"},
    {'G', "71", L, "lathe roughing cycle", "токарный цикл черновой обработки"},
    {'G', "71.1", L, "lathe roughing cycle", "токарный цикл черновой обработки"},
    {'G', "71.2", L, "lathe roughing cycle", "токарный цикл черновой обработки"},
    {'G', "72", L, "lathe facing cycle", "токарный цикл торцевой обработки"},
    {'G', "72.1", L, "lathe facing cycle", "токарный цикл торцевой обработки"},
    {'G', "72.2", L, "lathe facing cycle", "токарный цикл торцевой обработки"},
    {'G', "73", A, "drilling cycle with chip breaking", "цикл сверления с дроблением стружки"},
    {'G', "74", A, "left-hand tapping cycle with dwell", "цикл нарезания левой резьбы с паузой"},
    {'G', "76", L, "threading cycle", "цикл нарезания резьбы"},
    {'G', "80", A, "cancel canned cycle", "отмена постоянного цикла"},
    {'G', "81", A, "drilling cycle", "цикл сверления"},
    {'G', "82", A, "drilling cycle with dwell", "цикл сверления с паузой"},
    {'G', "83", A, "peck drilling cycle", "цикл прерывистого сверления"},
    {'G', "84", A, "right-hand tapping cycle with dwell", "цикл нарезания правой резьбы с паузой"},
    {'G', "85", A, "boring cycle, feed out", "цикл растачивания, вывод на подаче"},
    {'G', "86", A, "boring cycle, spindle stop, rapid out", "цикл растачивания, останов шпинделя, быстрый вывод"},
    {'G', "87", A, "back boring cycle", "цикл обратного растачивания"},
    {'G', "88", A, "boring cycle, spindle stop, manual out", "цикл растачивания, останов шпинделя, ручной вывод"},
    {'G', "89", A, "boring cycle with dwell, feed out", "цикл растачивания с паузой, вывод на подаче"},
    {'G', "90", A, "absolute distance mode", "абсолютные размеры"},
    {'G', "91", A, "incremental distance mode", "размеры в приращениях"},
    {'G', "90.1", A, "absolute arc centres (I J K)", "абсолютные центры дуг (I J K)"},
    {'G', "91.1", A, "incremental arc centres (I J K)", "центры дуг в приращениях (I J K)"},
    {'G', "92", A, "coordinate system offset", "смещение системы координат"},
    {'G', "92.1", A, "reset G92 offsets, clear the parameters", "сброс смещений G92 с очисткой параметров"},
    {'G', "92.2", A, "reset G92 offsets", "сброс смещений G92"},
    {'G', "92.3", A, "restore G92 offsets", "восстановление смещений G92"},
    {'G', "93", A, "inverse time feed", "подача в функции, обратной времени"},
    {'G', "94", A, "units per minute feed", "подача в единицах в минуту"},
    {'G', "95", A, "units per revolution feed", "подача в единицах на оборот"},
    {'G', "96", A, "constant surface speed", "постоянная скорость резания"},
    {'G', "97", A, "RPM mode", "обороты в минуту"},
    {'G', "98", A, "canned cycle: retract to the initial level", "постоянный цикл: отвод на исходный уровень"},
    {'G', "99", A, "canned cycle: retract to the R level", "постоянный цикл: отвод на уровень R"},
    {'M', "0", A, "program pause", "пауза программы"},
    {'M', "1", A, "optional pause", "пауза с подтверждением"},
    {'M', "2", A, "end of program", "конец программы"},
    {'M', "3", A, "spindle clockwise", "вращение шпинделя по часовой стрелке"},
    {'M', "4", A, "spindle counter-clockwise", "вращение шпинделя против часовой стрелки"},
    {'M', "5", A, "spindle stop", "останов шпинделя"},
    {'M', "6", A, "tool change", "смена инструмента"},
    {'M', "7", A, "mist coolant on", "включение охлаждения туманом"},
    {'M', "8", A, "flood coolant on", "включение охлаждения жидкостью"},
    {'M', "9", A, "coolant off", "отключение охлаждения"},
    {'M', "19", A, "spindle orientation", "ориентация шпинделя"},
    {'M', "30", A, "end of program, pallet change", "конец программы, смена паллеты"},
    {'M', "48", A, "feed and speed overrides on", "коррекции подачи и оборотов вкл."},
    {'M', "49", A, "feed and speed overrides off", "коррекции подачи и оборотов выкл."},
    {'M', "50", A, "feed override control", "управление коррекцией подачи"},
    {'M', "51", A, "spindle speed override control", "управление коррекцией оборотов"},
    {'M', "52", A, "adaptive feed control", "адаптивное управление подачей"},
    {'M', "53", A, "feed stop control", "управление остановом подачи"},
    {'M', "60", A, "pallet change pause", "пауза для смены паллеты"},
    {'M', "61", A, "set the current tool", "задание текущего инструмента"},
    {'M', "62", A, "digital output on, with motion", "цифровой выход вкл. с перемещением"},
    {'M', "63", A, "digital output off, with motion", "цифровой выход выкл. с перемещением"},
    {'M', "64", A, "digital output on, at once", "цифровой выход вкл. сразу"},
    {'M', "65", A, "digital output off, at once", "цифровой выход выкл. сразу"},
    {'M', "66", A, "wait on an input", "ожидание входа"},
    {'M', "67", A, "analog output, with motion", "аналоговый выход с перемещением"},
    {'M', "68", A, "analog output, at once", "аналоговый выход сразу"},
    {'M', "70", A, "save the modal state", "сохранение модального состояния"},
    {'M', "71", A, "invalidate the saved modal state", "отмена сохранённого модального состояния"},
    {'M', "72", A, "restore the modal state", "восстановление модального состояния"},
    {'M', "73", A, "save the modal state, restored at return", "сохранение модального состояния до возврата"},
    {'M', "98", A, "subprogram call (Fanuc style)", "вызов подпрограммы (как у Fanuc)"},
    {'M', "99", A, "end of subprogram (Fanuc style)", "конец подпрограммы (как у Fanuc)"},
};

constexpr CodeRange linuxcnc_ranges[] = {
    {'M', 100, 199, "user-defined M code", "M-код пользователя"},
};

// Some ГОСТ controls write M (and S, T) with three digits, the first 0 or 1: M102 is M02 given once the
// machine has acknowledged the commands before it (the 1991 course text, "S025, T103, M114").
constexpr CodeRange gost_ranges[] = {
    {'G', 0, 99, "", ""},
    {'M', 0, 199, "", ""},
};

struct Table {
    std::span<const Code> codes;
    std::span<const CodeRange> ranges;
};

Table table_of(Dialect d) {
    switch (d) {
        case Dialect::gost:
            return {{}, gost_ranges};
        case Dialect::fanuc:
            return {fanuc_codes, fanuc_ranges};
        case Dialect::linuxcnc:
            return {linuxcnc_codes, linuxcnc_ranges};
        default:
            return {};
    }
}

// The whole number a value is, when it is one.
std::optional<int> whole(std::string_view value) {
    int n = 0;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc{} || end != value.data() + value.size()) return std::nullopt;
    return n;
}

const CodeRange* range_of(const Table& t, char letter, std::string_view value) {
    auto n = whole(value);
    if (!n) return nullptr;
    for (const auto& r : t.ranges)
        if (r.letter == letter && *n >= r.from && *n <= r.to) return &r;
    return nullptr;
}

}  // namespace

std::string code_value(std::string_view written) {
    if (written.empty() || written.find_first_not_of("0123456789.") != std::string_view::npos) return "";
    auto point = written.find('.');
    if (point != std::string_view::npos && written.find('.', point + 1) != std::string_view::npos) return "";
    std::string_view whole_part = written.substr(0, point), fraction;
    if (point != std::string_view::npos) fraction = written.substr(point + 1);
    while (whole_part.size() > 1 && whole_part.front() == '0') whole_part.remove_prefix(1);
    while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
    std::string v(whole_part.empty() ? "0" : whole_part);
    if (!fraction.empty()) v += "." + std::string(fraction);
    return v;
}

bool code_known(Dialect d, char letter, std::string_view value) {
    Table t = table_of(d);
    if ((letter != 'G' && letter != 'M') || (t.codes.empty() && t.ranges.empty())) return true;
    std::string v = code_value(value);
    if (v.empty()) return true;
    if (range_of(t, letter, v)) return true;
    return std::any_of(t.codes.begin(), t.codes.end(),
                       [&](const Code& c) { return c.letter == letter && c.value == v; });
}

std::vector<CodeMeaning> code_meanings(Dialect d, char letter, std::string_view value) {
    std::vector<CodeMeaning> out;
    std::string v = code_value(value);
    if (v.empty()) return out;
    if (d == Dialect::gost) {
        auto n = whole(v);
        bool acknowledged = letter == 'M' && n && *n >= 100 && *n <= 199;
        if (const NcFunction* f = n ? find_nc_function(letter, acknowledged ? *n - 100 : *n) : nullptr)
            out.push_back({Machine::any,
                           std::string(f->en) + (acknowledged ? " (after the machine's acknowledgement)" : ""),
                           std::string(f->ru) + (acknowledged ? " (после подтверждения станком)" : "")});
        return out;
    }
    Table t = table_of(d);
    for (const auto& c : t.codes)
        if (c.letter == letter && c.value == v) out.push_back({c.machine, std::string(c.en), std::string(c.ru)});
    if (const CodeRange* r = range_of(t, letter, v); out.empty() && r && !r->en.empty())
        out.push_back({Machine::any, std::string(r->en), std::string(r->ru)});
    return out;
}

// The arguments of a macro call (G65, G66) are letters of its own: they say nothing of the machine.
void MachineEvidence::block(const Block& b) {
    auto has_g = [&](std::initializer_list<long long> codes) {
        return std::any_of(b.words.begin(), b.words.end(), [&](const Word& w) {
            return w.address == 'G' && w.integer() &&
                   std::find(codes.begin(), codes.end(), *w.integer()) != codes.end();
        });
    };
    if (has_g({65, 66})) return;
    bool spindle_limit =
        has_g({50}) && std::any_of(b.words.begin(), b.words.end(), [](const Word& w) { return w.address == 'S'; });
    lathe_ += spindle_limit || has_g({18, 7});
    mill_ += has_g({17});
    for (const auto& w : b.words) {
        if (!w.known) continue;
        mill_ += w.address == 'Y' || w.address == 'H';
        lathe_ += w.address == 'U' || w.address == 'W' ||
                  (w.address == 'T' && !w.has_point() && !w.macro && w.digits().size() == 4);
    }
}

Machine MachineEvidence::machine() const {
    if (lathe_ && !mill_) return Machine::lathe;
    if (mill_ && !lathe_) return Machine::mill;
    return Machine::any;
}

std::string explain_codes(const Block& b, Dialect d, Machine machine, bool russian) {
    std::string out;
    for (const auto& w : b.words) {
        if ((w.address != 'G' && w.address != 'M') || !w.known || w.macro || w.sign) continue;
        std::vector<CodeMeaning> all = code_meanings(d, w.address, code_value(std::string_view(w.text).substr(1)));
        std::string named;
        for (const auto& m : all) {
            if (machine != Machine::any && m.machine != Machine::any && m.machine != machine) continue;
            std::string where;
            if (machine == Machine::any && m.machine != Machine::any && all.size() > 1)
                where = m.machine == Machine::lathe ? (russian ? " (токарные)" : " (lathe)")
                                                    : (russian ? " (фрезерные)" : " (mill)");
            named += (named.empty() ? "" : " / ") + (russian ? m.ru : m.en) + where;
        }
        if (!named.empty()) out += (out.empty() ? "" : ", ") + w.text + " " + named;
    }
    return out;
}

}  // namespace tape
